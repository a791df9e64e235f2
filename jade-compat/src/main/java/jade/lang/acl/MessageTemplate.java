package jade.lang.acl;

import jade.core.AID;

import java.util.Date;
import java.util.Objects;

/**
 * JADE's message template: a test on messages, made with the static {@code Match*} factories and
 * combined with {@link #and}, {@link #or} and {@link #not}; used by {@link jade.core.Agent#receive}.
 */
public class MessageTemplate implements jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;

    /** Any test on a message, for templates of your own. */
    public interface MatchExpression extends jade.util.leap.Serializable {
        boolean match(ACLMessage msg);
    }

    private final MatchExpression expression;
    private final String description;

    /** A template from a test of your own. */
    public MessageTemplate(MatchExpression e) {
        this(e, "( Custom " + e + " )");
    }

    private MessageTemplate(MatchExpression e, String description) {
        this.expression = Objects.requireNonNull(e, "expression");
        this.description = description;
    }

    /** True if the message fits. */
    public boolean match(ACLMessage msg) {
        return expression.match(msg);
    }

    public static MessageTemplate MatchAll() {
        return new MessageTemplate(m -> true, "( Match All )");
    }

    public static MessageTemplate MatchSender(AID value) {
        return new MessageTemplate(m -> value.equals(m.getSender()), "( Sender: " + value.getName() + " )");
    }

    /** Every AID given is among the message's receivers. */
    public static MessageTemplate MatchReceiver(AID[] values) {
        return new MessageTemplate(m -> containsAll(m.getAllReceiver(), values), "( Receivers: " + values.length + " )");
    }

    /** Messages on a topic: here, a receiver equal to the topic's AID. */
    public static MessageTemplate MatchTopic(AID topic) {
        return new MessageTemplate(m -> containsAll(m.getAllReceiver(), new AID[] {topic}), "( Topic: " + topic.getName() + " )");
    }

    /** Every AID given is among the message's reply-to. */
    public static MessageTemplate MatchReplyTo(AID[] values) {
        return new MessageTemplate(m -> containsAll(m.getAllReplyTo(), values), "( ReplyTo: " + values.length + " )");
    }

    public static MessageTemplate MatchContent(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getContent()), "( Content: " + value + " )");
    }

    public static MessageTemplate MatchReplyWith(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getReplyWith()), "( ReplyWith: " + value + " )");
    }

    public static MessageTemplate MatchInReplyTo(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getInReplyTo()), "( InReplyTo: " + value + " )");
    }

    public static MessageTemplate MatchLanguage(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getLanguage()), "( Language: " + value + " )");
    }

    public static MessageTemplate MatchEncoding(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getEncoding()), "( Encoding: " + value + " )");
    }

    public static MessageTemplate MatchOntology(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getOntology()), "( Ontology: " + value + " )");
    }

    public static MessageTemplate MatchReplyByDate(Date value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getReplyByDate()), "( ReplyByDate: " + value + " )");
    }

    public static MessageTemplate MatchProtocol(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getProtocol()), "( Protocol: " + value + " )");
    }

    public static MessageTemplate MatchConversationId(String value) {
        return new MessageTemplate(m -> Objects.equals(value, m.getConversationId()), "( ConversationId: " + value + " )");
    }

    public static MessageTemplate MatchPerformative(int value) {
        return new MessageTemplate(m -> m.getPerformative() == value, "( Perfomative: " + ACLMessage.getPerformative(value) + " )");
    }

    /**
     * Every field set in the example must be equal in the message ({@code matchPerformative}: the
     * performative too); receivers and reply-to of the example must all be in the message's.
     */
    public static MessageTemplate MatchCustom(ACLMessage example, boolean matchPerformative) {
        ACLMessage ex = (ACLMessage) example.clone();
        return new MessageTemplate(m -> {
            if (matchPerformative && m.getPerformative() != ex.getPerformative()) {
                return false;
            }
            return (ex.getSender() == null || ex.getSender().equals(m.getSender()))
                    && same(ex.getContent(), m.getContent()) && same(ex.getReplyWith(), m.getReplyWith())
                    && same(ex.getInReplyTo(), m.getInReplyTo()) && same(ex.getEncoding(), m.getEncoding())
                    && same(ex.getLanguage(), m.getLanguage()) && same(ex.getOntology(), m.getOntology())
                    && same(ex.getProtocol(), m.getProtocol()) && same(ex.getConversationId(), m.getConversationId())
                    && (ex.getReplyByDate() == null || ex.getReplyByDate().equals(m.getReplyByDate()))
                    && containsAll(m.getAllReceiver(), toArray(ex.getAllReceiver()))
                    && containsAll(m.getAllReplyTo(), toArray(ex.getAllReplyTo()));
        }, "( Custom )");
    }

    public static MessageTemplate and(MessageTemplate a, MessageTemplate b) {
        return new MessageTemplate(m -> a.match(m) && b.match(m), "( AND " + a + " " + b + " )");
    }

    public static MessageTemplate or(MessageTemplate a, MessageTemplate b) {
        return new MessageTemplate(m -> a.match(m) || b.match(m), "( OR " + a + " " + b + " )");
    }

    public static MessageTemplate not(MessageTemplate a) {
        return new MessageTemplate(m -> !a.match(m), "( NOT " + a + " )");
    }

    @Override
    public String toString() {
        return description;
    }

    private static boolean same(String example, String actual) {
        return example == null || example.equals(actual);
    }

    private static AID[] toArray(jade.util.leap.Iterator it) {
        java.util.List<AID> l = new java.util.ArrayList<>();
        while (it.hasNext()) {
            l.add((AID) it.next());
        }
        return l.toArray(new AID[0]);
    }

    private static boolean containsAll(jade.util.leap.Iterator it, AID[] values) {
        java.util.List<AID> have = java.util.Arrays.asList(toArray(it));
        for (AID v : values) {
            if (!have.contains(v)) {
                return false;
            }
        }
        return true;
    }
}
