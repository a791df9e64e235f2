package io.concord.core.acl;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;

/**
 * A FIPA ACL message (SC00061): a performative and the FIPA parameters, plus user-defined
 * parameters. Mutable, like JADE's {@code ACLMessage}, so that code written for JADE reads the same.
 *
 * <p>The content is either text or a byte sequence; {@link #getContent()} and
 * {@link #getByteSequenceContent()} convert between the two with UTF-8 when asked for the other.
 *
 * <p>User-defined parameter names are kept without the {@code X-} prefix that the string
 * representation adds: {@code addUserDefinedParameter("X-foo", v)} and
 * {@code addUserDefinedParameter("foo", v)} name the same parameter.
 */
public final class AclMessage {
    /** No {@code :reply-by} set. */
    public static final long NO_REPLY_BY = Long.MIN_VALUE;

    private static final AtomicLong REPLY_WITH_FALLBACK = new AtomicLong();

    private Performative performative;
    private AID sender;
    private List<AID> receivers;
    private Supplier<List<AID>> lazyReceivers;
    /** Null until asked for or added to: most messages have none, and each message is allocated on every hand-over. */
    private List<AID> replyTo;
    private String content;
    private byte[] byteContent;
    private String language;
    private String encoding;
    private String ontology;
    private String protocol;
    private String conversationId;
    private String replyWith;
    private String inReplyTo;
    private long replyByEpochMs = NO_REPLY_BY;
    private Map<String, String> userParameters;
    private long receivedAtEpochMs = Long.MIN_VALUE;

    /** A message with the given performative and no other parameter. */
    public AclMessage(Performative performative) {
        this.performative = Objects.requireNonNull(performative, "performative");
    }

    public Performative getPerformative() {
        return performative;
    }

    public AclMessage setPerformative(Performative p) {
        this.performative = Objects.requireNonNull(p, "performative");
        return this;
    }

    public AID getSender() {
        return sender;
    }

    public AclMessage setSender(AID sender) {
        this.sender = sender;
        return this;
    }

    /** The receivers, in order; a live, modifiable list. */
    public List<AID> getReceivers() {
        return receivers();
    }

    private List<AID> receivers() {
        if (receivers == null) {
            receivers = lazyReceivers == null ? new ArrayList<>(1) : new ArrayList<>(lazyReceivers.get());
            lazyReceivers = null;
        }
        return receivers;
    }

    /**
     * For codecs: the receivers will be built by {@code decoder} when first asked for. A receiver of a
     * message to many agents rarely reads the list; building it is much of the cost of decoding.
     * The decoder must have validated the bytes already: it must not fail.
     */
    public void setReceiversLazily(Supplier<List<AID>> decoder) {
        this.receivers = null;
        this.lazyReceivers = Objects.requireNonNull(decoder, "decoder");
    }

    public AclMessage addReceiver(AID receiver) {
        receivers().add(Objects.requireNonNull(receiver, "receiver"));
        return this;
    }

    public AclMessage clearAllReceiver() {
        receivers = new ArrayList<>(1);
        lazyReceivers = null;
        return this;
    }

    /** The reply-to agents, in order; a live, modifiable list. */
    public List<AID> getReplyTo() {
        if (replyTo == null) {
            replyTo = new ArrayList<>(1);
        }
        return replyTo;
    }

    public AclMessage addReplyTo(AID aid) {
        getReplyTo().add(Objects.requireNonNull(aid, "reply-to"));
        return this;
    }

    private boolean hasReplyTo() {
        return replyTo != null && !replyTo.isEmpty();
    }

    /** The content as text (byte content is decoded as UTF-8), or {@code null} if there is none. */
    public String getContent() {
        if (content == null && byteContent != null) {
            return new String(byteContent, StandardCharsets.UTF_8);
        }
        return content;
    }

    /** Sets text content, replacing any byte content. */
    public AclMessage setContent(String content) {
        this.content = content;
        this.byteContent = null;
        return this;
    }

    /** The content as bytes (text content is encoded as UTF-8), or {@code null} if there is none. */
    public byte[] getByteSequenceContent() {
        if (byteContent == null && content != null) {
            return content.getBytes(StandardCharsets.UTF_8);
        }
        return byteContent == null ? null : byteContent.clone();
    }

    /** Sets byte content, replacing any text content. */
    public AclMessage setByteSequenceContent(byte[] bytes) {
        this.byteContent = bytes == null ? null : bytes.clone();
        this.content = null;
        return this;
    }

    /** True if the content was given as a byte sequence rather than as text. */
    public boolean hasByteSequenceContent() {
        return byteContent != null;
    }

    public String getLanguage() {
        return language;
    }

    public AclMessage setLanguage(String language) {
        this.language = language;
        return this;
    }

    public String getEncoding() {
        return encoding;
    }

    public AclMessage setEncoding(String encoding) {
        this.encoding = encoding;
        return this;
    }

    public String getOntology() {
        return ontology;
    }

    public AclMessage setOntology(String ontology) {
        this.ontology = ontology;
        return this;
    }

    public String getProtocol() {
        return protocol;
    }

    public AclMessage setProtocol(String protocol) {
        this.protocol = protocol;
        return this;
    }

    public String getConversationId() {
        return conversationId;
    }

    public AclMessage setConversationId(String conversationId) {
        this.conversationId = conversationId;
        return this;
    }

    public String getReplyWith() {
        return replyWith;
    }

    public AclMessage setReplyWith(String replyWith) {
        this.replyWith = replyWith;
        return this;
    }

    public String getInReplyTo() {
        return inReplyTo;
    }

    public AclMessage setInReplyTo(String inReplyTo) {
        this.inReplyTo = inReplyTo;
        return this;
    }

    /** The {@code :reply-by} deadline in epoch milliseconds, or {@link #NO_REPLY_BY}. */
    public long getReplyByEpochMs() {
        return replyByEpochMs;
    }

    public AclMessage setReplyByEpochMs(long epochMs) {
        this.replyByEpochMs = epochMs;
        return this;
    }

    public boolean hasReplyBy() {
        return replyByEpochMs != NO_REPLY_BY;
    }

    /** User-defined parameters, without their {@code X-} prefix, in insertion order (read-only view). */
    public Map<String, String> getUserDefinedParameters() {
        return userParameters == null ? Map.of() : Collections.unmodifiableMap(userParameters);
    }

    /** The value of a user-defined parameter (with or without the {@code X-} prefix), or {@code null}. */
    public String getUserDefinedParameter(String key) {
        return userParameters == null ? null : userParameters.get(stripX(key));
    }

    /** Adds or replaces a user-defined parameter; a leading {@code X-} in the key is dropped. */
    public AclMessage addUserDefinedParameter(String key, String value) {
        Objects.requireNonNull(value, "value");
        String k = stripX(Objects.requireNonNull(key, "key"));
        if (!isParameterName(k)) {
            throw new IllegalArgumentException("a user-defined parameter name must be a word of letters, digits, "
                    + "'-', '_' or '.', starting with a letter; got '" + key + "'");
        }
        if (userParameters == null) {
            userParameters = new LinkedHashMap<>(4);
        }
        userParameters.put(k, value);
        return this;
    }

    public AclMessage removeUserDefinedParameter(String key) {
        if (userParameters != null) {
            userParameters.remove(stripX(key));
        }
        return this;
    }

    /** True if the name can stand after {@code :X-} in the string representation. */
    public static boolean isParameterName(String k) {
        if (k.isEmpty() || !Character.isLetter(k.charAt(0)) || k.charAt(0) >= 0x80) {
            return false;
        }
        for (int i = 1; i < k.length(); i++) {
            char c = k.charAt(i);
            if (!(c < 0x80 && (Character.isLetterOrDigit(c) || c == '-' || c == '_' || c == '.'))) {
                return false;
            }
        }
        return true;
    }

    private static String stripX(String key) {
        String k = key;
        while (k.length() > 2 && (k.charAt(0) == 'X' || k.charAt(0) == 'x') && k.charAt(1) == '-') {
            k = k.substring(2);
        }
        return k;
    }

    /**
     * When the runtime handed this message to the receiving agent, in the platform's epoch
     * milliseconds; {@code Long.MIN_VALUE} for a message that was not received.
     */
    public long getReceivedAtEpochMs() {
        return receivedAtEpochMs;
    }

    /** Set by the runtime on delivery. */
    public void setReceivedAtEpochMs(long epochMs) {
        this.receivedAtEpochMs = epochMs;
    }

    /**
     * A reply with JADE's semantics: same performative (set the one you mean), receivers from
     * {@code :reply-to} if present, else the sender; the same conversation-id, protocol, language,
     * ontology and encoding; {@code :in-reply-to} set to this message's {@code :reply-with}; and a
     * new {@code :reply-with} made of the original sender's name and the time the message was
     * received (the platform's clock, so a simulation stays deterministic).
     */
    public AclMessage createReply() {
        AclMessage reply = new AclMessage(performative);
        if (hasReplyTo()) {
            reply.receivers().addAll(replyTo);
        } else if (sender != null) {
            reply.receivers().add(sender);
        }
        reply.language = language;
        reply.ontology = ontology;
        reply.protocol = protocol;
        reply.encoding = encoding;
        reply.conversationId = conversationId;
        reply.inReplyTo = replyWith;
        long stamp = receivedAtEpochMs != Long.MIN_VALUE ? receivedAtEpochMs : REPLY_WITH_FALLBACK.incrementAndGet();
        reply.replyWith = (sender != null ? sender.name() : "reply") + stamp;
        return reply;
    }

    /** A deep copy. */
    public AclMessage copy() {
        AclMessage m = new AclMessage(performative);
        m.sender = sender;
        List<AID> to = receivers();
        if (to.size() == 1) {
            m.receivers = new ArrayList<>(1);
            m.receivers.add(to.get(0));
        } else {
            m.receivers = new ArrayList<>(to);
        }
        if (hasReplyTo()) {
            m.replyTo = new ArrayList<>(replyTo);
        }
        m.content = content;
        m.byteContent = byteContent == null ? null : byteContent.clone();
        m.language = language;
        m.encoding = encoding;
        m.ontology = ontology;
        m.protocol = protocol;
        m.conversationId = conversationId;
        m.replyWith = replyWith;
        m.inReplyTo = inReplyTo;
        m.replyByEpochMs = replyByEpochMs;
        m.userParameters = userParameters == null ? null : new LinkedHashMap<>(userParameters);
        m.receivedAtEpochMs = receivedAtEpochMs;
        return m;
    }

    /**
     * True if every parameter is equal, AIDs compared slot by slot and the content compared as the
     * kind it was given in. The receive time is not compared.
     */
    public boolean sameAs(AclMessage o) {
        return o != null && performative == o.performative && aidEq(sender, o.sender)
                && aidsEq(receivers(), o.receivers()) && aidsEq(hasReplyTo() ? replyTo : List.of(), o.hasReplyTo() ? o.replyTo : List.of())
                && Objects.equals(content, o.content) && Arrays.equals(byteContent, o.byteContent)
                && Objects.equals(language, o.language) && Objects.equals(encoding, o.encoding)
                && Objects.equals(ontology, o.ontology) && Objects.equals(protocol, o.protocol)
                && Objects.equals(conversationId, o.conversationId) && Objects.equals(replyWith, o.replyWith)
                && Objects.equals(inReplyTo, o.inReplyTo) && replyByEpochMs == o.replyByEpochMs
                && getUserDefinedParameters().equals(o.getUserDefinedParameters());
    }

    private static boolean aidEq(AID a, AID b) {
        return a == null ? b == null : a.fullyEquals(b);
    }

    private static boolean aidsEq(List<AID> a, List<AID> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            if (!a.get(i).fullyEquals(b.get(i))) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        return FipaStringWriter.write(this, false);
    }
}
