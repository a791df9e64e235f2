package jade.lang.acl;

import jade.core.AID;
import jade.util.leap.ArrayList;
import jade.util.leap.Iterator;
import jade.util.leap.Properties;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.util.Date;
import java.util.Locale;

/**
 * JADE's ACL message, with JADE's int performatives ({@link #INFORM} is 7, as in JADE 4.3) and
 * every FIPA field. Sent by {@link jade.core.Agent#send}; Concord carries it as its own
 * {@code AclMessage}.
 */
public class ACLMessage implements Cloneable, jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;

    public static final int ACCEPT_PROPOSAL = 0;
    public static final int AGREE = 1;
    public static final int CANCEL = 2;
    public static final int CFP = 3;
    public static final int CONFIRM = 4;
    public static final int DISCONFIRM = 5;
    public static final int FAILURE = 6;
    public static final int INFORM = 7;
    public static final int INFORM_IF = 8;
    public static final int INFORM_REF = 9;
    public static final int NOT_UNDERSTOOD = 10;
    public static final int PROPOSE = 11;
    public static final int QUERY_IF = 12;
    public static final int QUERY_REF = 13;
    public static final int REFUSE = 14;
    public static final int REJECT_PROPOSAL = 15;
    public static final int REQUEST = 16;
    public static final int REQUEST_WHEN = 17;
    public static final int REQUEST_WHENEVER = 18;
    public static final int SUBSCRIBE = 19;
    public static final int PROXY = 20;
    public static final int PROPAGATE = 21;
    public static final int UNKNOWN = -1;

    public static final String IGNORE_FAILURE = "JADE-ignore-failure";
    public static final String DONT_NOTIFY_FAILURE = "JADE-dont-notify-failure";
    public static final String TRACE = "JADE-trace";
    public static final String NO_CLONE = "JADE-no-clone";
    public static final String SYNCH_DELIVERY = "JADE-synch-delivery";
    public static final String REAL_SENDER = "JADE-real-sender";
    public static final String SF_TIMEOUT = "JADE-SF-timeout";
    public static final String AMS_FAILURE_AGENT_NOT_FOUND = "Agent not found";
    public static final String AMS_FAILURE_AGENT_UNREACHABLE = "Agent unreachable";
    public static final String AMS_FAILURE_SERVICE_ERROR = "Service error";
    public static final String AMS_FAILURE_UNAUTHORIZED = "Not authorized";
    public static final String AMS_FAILURE_FOREIGN_AGENT_UNREACHABLE = "Foreign agent unreachable";
    public static final String AMS_FAILURE_FOREIGN_AGENT_NO_ADDRESS = "Foreign agent with no address";
    public static final String AMS_FAILURE_UNEXPECTED_ERROR = "Unexpected error";

    private static final String[] NAMES = {"ACCEPT-PROPOSAL", "AGREE", "CANCEL", "CFP", "CONFIRM", "DISCONFIRM",
        "FAILURE", "INFORM", "INFORM-IF", "INFORM-REF", "NOT-UNDERSTOOD", "PROPOSE", "QUERY-IF", "QUERY-REF",
        "REFUSE", "REJECT-PROPOSAL", "REQUEST", "REQUEST-WHEN", "REQUEST-WHENEVER", "SUBSCRIBE", "PROXY",
        "PROPAGATE"};

    private static long replyCounter;

    private int performative;
    private AID sender;
    private ArrayList receivers = new ArrayList();
    private ArrayList replyTo = new ArrayList();
    private String content;
    private byte[] byteContent;
    private String replyWith;
    private String inReplyTo;
    private String encoding;
    private String language;
    private String ontology;
    private long replyBy = Long.MIN_VALUE;
    private String protocol;
    private String conversationId;
    private Properties userParams = new Properties();
    private long postTimeStamp = -1;

    /** A message with performative {@link #NOT_UNDERSTOOD}, as JADE's no-argument constructor makes. */
    public ACLMessage() {
        this(NOT_UNDERSTOOD);
    }

    /** A message with a performative, one of this class's constants. */
    public ACLMessage(int perf) {
        this.performative = perf;
    }

    /** The performatives' names, indexed by their int values. */
    public static String[] getAllPerformativeNames() {
        return NAMES.clone();
    }

    /** The name of a performative ({@code "INFORM"}), or {@code "UNKNOWN"}. */
    public static String getPerformative(int perf) {
        return perf >= 0 && perf < NAMES.length ? NAMES[perf] : "UNKNOWN";
    }

    /** The int value of a performative's name, in any case; {@link #UNKNOWN} if none. */
    public static int getInteger(String perf) {
        String p = perf.toUpperCase(Locale.ROOT);
        for (int i = 0; i < NAMES.length; i++) {
            if (NAMES[i].equals(p)) {
                return i;
            }
        }
        return UNKNOWN;
    }

    public void setSender(AID s) {
        this.sender = s == null ? null : (AID) s.clone();
    }

    public AID getSender() {
        return sender;
    }

    public void addReceiver(AID r) {
        if (r != null) {
            receivers.add(r);
        }
    }

    public boolean removeReceiver(AID r) {
        return receivers.remove(r);
    }

    public void clearAllReceiver() {
        receivers.clear();
    }

    public Iterator getAllReceiver() {
        return receivers.iterator();
    }

    /** The receivers this message is meant for: here, its receivers. */
    public Iterator getAllIntendedReceiver() {
        return receivers.iterator();
    }

    public void addReplyTo(AID r) {
        if (r != null) {
            replyTo.add(r);
        }
    }

    public boolean removeReplyTo(AID r) {
        return replyTo.remove(r);
    }

    public void clearAllReplyTo() {
        replyTo.clear();
    }

    public Iterator getAllReplyTo() {
        return replyTo.iterator();
    }

    public void setPerformative(int perf) {
        this.performative = perf;
    }

    public int getPerformative() {
        return performative;
    }

    /** Sets text content (and drops byte content). */
    public void setContent(String c) {
        this.byteContent = null;
        this.content = c;
    }

    /** The content as text; for byte content, its bytes as ISO-8859-1 text. */
    public String getContent() {
        if (byteContent != null) {
            return new String(byteContent, java.nio.charset.StandardCharsets.ISO_8859_1);
        }
        return content;
    }

    /** Sets byte content (and drops text content). */
    public void setByteSequenceContent(byte[] c) {
        this.content = null;
        this.byteContent = c;
    }

    public byte[] getByteSequenceContent() {
        if (byteContent != null) {
            return byteContent;
        }
        return content == null ? null : content.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
    }

    public boolean hasByteSequenceContent() {
        return byteContent != null;
    }

    /**
     * Sets the content to a Java object, by Java serialisation, as byte content (Concord carries
     * the bytes as they are; its FIPA string codec writes them as JADE does, in Base64).
     */
    public void setContentObject(Serializable s) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(s);
        }
        setByteSequenceContent(bytes.toByteArray());
    }

    /** The content as a Java object, read back by Java serialisation. */
    public Serializable getContentObject() throws UnreadableException {
        byte[] b = getByteSequenceContent();
        if (b == null) {
            return null;
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(b)) {
            @Override
            protected Class<?> resolveClass(java.io.ObjectStreamClass desc) throws IOException, ClassNotFoundException {
                try {
                    return Class.forName(desc.getName(), false, Thread.currentThread().getContextClassLoader());
                } catch (ClassNotFoundException e) {
                    return super.resolveClass(desc);
                }
            }
        }) {
            return (Serializable) in.readObject();
        } catch (IOException | ClassNotFoundException | ClassCastException e) {
            throw new UnreadableException(e.getMessage());
        }
    }

    public void setReplyWith(String v) {
        this.replyWith = v;
    }

    public String getReplyWith() {
        return replyWith;
    }

    public void setInReplyTo(String v) {
        this.inReplyTo = v;
    }

    public String getInReplyTo() {
        return inReplyTo;
    }

    public void setEncoding(String v) {
        this.encoding = v;
    }

    public String getEncoding() {
        return encoding;
    }

    public void setLanguage(String v) {
        this.language = v;
    }

    public String getLanguage() {
        return language;
    }

    public void setOntology(String v) {
        this.ontology = v;
    }

    public String getOntology() {
        return ontology;
    }

    public void setReplyByDate(Date d) {
        this.replyBy = d == null ? Long.MIN_VALUE : d.getTime();
    }

    public Date getReplyByDate() {
        return replyBy == Long.MIN_VALUE ? null : new Date(replyBy);
    }

    /** The reply-by date as FIPA writes it ({@code yyyyMMdd'T'HHmmssSSS'Z'}, UTC), or null. */
    public String getReplyBy() {
        if (replyBy == Long.MIN_VALUE) {
            return null;
        }
        java.time.format.DateTimeFormatter f = java.time.format.DateTimeFormatter.ofPattern("yyyyMMdd'T'HHmmssSSS'Z'")
                .withZone(java.time.ZoneOffset.UTC);
        return f.format(java.time.Instant.ofEpochMilli(replyBy));
    }

    public void setProtocol(String v) {
        this.protocol = v;
    }

    public String getProtocol() {
        return protocol;
    }

    public void setConversationId(String v) {
        this.conversationId = v;
    }

    public String getConversationId() {
        return conversationId;
    }

    public void addUserDefinedParameter(String key, String value) {
        userParams.setProperty(key, value);
    }

    public String getUserDefinedParameter(String key) {
        return userParams.getProperty(key);
    }

    public Properties getAllUserDefinedParameters() {
        return userParams;
    }

    public void setAllUserDefinedParameters(Properties p) {
        userParams = p == null ? new Properties() : p;
    }

    public boolean removeUserDefinedParameter(String key) {
        return userParams.remove(key) != null;
    }

    public Object clearUserDefinedParameter(String key) {
        return userParams.remove(key);
    }

    /** Stamps the message with the time it was posted (set on delivery). */
    public void setPostTimeStamp() {
        postTimeStamp = io.concord.jadecompat.internal.Engine.nowMs();
    }

    void setPostTimeStamp(long ms) {
        postTimeStamp = ms;
    }

    public long getPostTimeStamp() {
        return postTimeStamp;
    }

    /** Clears every field; the performative becomes {@link #NOT_UNDERSTOOD}. */
    public void reset() {
        performative = NOT_UNDERSTOOD;
        sender = null;
        receivers = new ArrayList();
        replyTo = new ArrayList();
        content = null;
        byteContent = null;
        replyWith = null;
        inReplyTo = null;
        encoding = null;
        language = null;
        ontology = null;
        replyBy = Long.MIN_VALUE;
        protocol = null;
        conversationId = null;
        userParams = new Properties();
        postTimeStamp = -1;
    }

    /**
     * A reply, as JADE makes it: the same performative (set the one you mean), receivers from
     * {@code :reply-to} if there are any, else the sender; the same conversation-id, protocol,
     * language and ontology (not the encoding, nor user-defined parameters, as in JADE 4.3);
     * {@code :in-reply-to} this message's {@code :reply-with};
     * and a new {@code :reply-with} of the sender's name and a number.
     */
    public ACLMessage createReply() {
        ACLMessage m = new ACLMessage(performative);
        if (!replyTo.isEmpty()) {
            for (Object r : replyTo.toArray()) {
                m.addReceiver((AID) ((AID) r).clone());
            }
        } else if (sender != null) {
            m.addReceiver((AID) sender.clone());
        }
        m.language = language;
        m.ontology = ontology;
        m.protocol = protocol;
        m.conversationId = conversationId;
        m.inReplyTo = replyWith;
        long stamp = postTimeStamp >= 0 ? postTimeStamp : nextReplyNumber();
        m.replyWith = (sender != null ? sender.getName() : "X") + stamp;
        return m;
    }

    private static synchronized long nextReplyNumber() {
        return ++replyCounter;
    }

    /** A copy: receivers, reply-to and parameters are copied, AIDs cloned. */
    @Override
    public synchronized Object clone() {
        ACLMessage m;
        try {
            m = (ACLMessage) super.clone();
        } catch (CloneNotSupportedException e) {
            throw new AssertionError(e);
        }
        m.receivers = new ArrayList();
        for (Object r : receivers.toArray()) {
            m.receivers.add(((AID) r).clone());
        }
        m.replyTo = new ArrayList();
        for (Object r : replyTo.toArray()) {
            m.replyTo.add(((AID) r).clone());
        }
        m.userParams = (Properties) userParams.clone();
        m.byteContent = byteContent == null ? null : byteContent.clone();
        return m;
    }

    /** The message in FIPA's string form (as JADE prints it, one slot a line). */
    @Override
    public String toString() {
        // JADE 4.3's layout, space for space (seen from its output; programs print messages to trace them)
        StringBuilder b = new StringBuilder("(").append(getPerformative(performative)).append('\n');
        if (sender != null) {
            b.append(" :sender  ").append(sender).append('\n');
        }
        if (!receivers.isEmpty()) {
            b.append(" :receiver  (set ");
            for (Object r : receivers.toArray()) {
                b.append(r).append(' ');
            }
            b.append(")\n");
        }
        if (!replyTo.isEmpty()) {
            b.append(" :reply-to  (set \n");
            for (Object r : replyTo.toArray()) {
                b.append(r).append(' ');
            }
            b.append(")\n");
        }
        String c = getContent();
        if (c != null && !c.isEmpty()) {
            b.append(" :content  \"").append(c.trim().replace("\"", "\\\"")).append("\" \n");
        }
        slot(b, "reply-with", replyWith, " ");
        slot(b, "in-reply-to", inReplyTo, " ");
        slot(b, "encoding", encoding, " ");
        slot(b, "language", language, " ");
        slot(b, "ontology", ontology, " ");
        slot(b, "reply-by", getReplyBy(), "\n");
        slot(b, "protocol", protocol, "\n");
        slot(b, "conversation-id", conversationId, " ");
        for (java.util.Enumeration<Object> e = userParams.keys(); e.hasMoreElements(); ) {
            String k = String.valueOf(e.nextElement());
            b.append(':').append(k.startsWith("X-") ? k : "X-" + k).append(' ').append(userParams.getProperty(k)).append(' ');
        }
        return b.append(")").toString();
    }

    private static void slot(StringBuilder b, String name, String v, String end) {
        if (v != null) {
            b.append(" :").append(name).append("  ").append(v).append(end);
        }
    }
}
