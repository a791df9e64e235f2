package io.concord.core.acl;

import java.util.Objects;
import java.util.function.Predicate;

/**
 * A test on messages, used to pick from an agent's mailbox. The static factories mirror JADE's
 * {@code MessageTemplate.Match*}; {@link #and}, {@link #or} and {@link #not} combine them. Any
 * lambda is a template too.
 */
@FunctionalInterface
public interface MessageTemplate {

    /** True if the message fits this template. */
    boolean match(AclMessage msg);

    /** A template that both this and the other must match. */
    default MessageTemplate and(MessageTemplate other) {
        Objects.requireNonNull(other, "other");
        return m -> match(m) && other.match(m);
    }

    /** A template that this or the other must match. */
    default MessageTemplate or(MessageTemplate other) {
        Objects.requireNonNull(other, "other");
        return m -> match(m) || other.match(m);
    }

    /** Matches every message. */
    static MessageTemplate matchAll() {
        return m -> true;
    }

    static MessageTemplate and(MessageTemplate a, MessageTemplate b) {
        return a.and(b);
    }

    static MessageTemplate or(MessageTemplate a, MessageTemplate b) {
        return a.or(b);
    }

    /** Matches what the given template does not. */
    static MessageTemplate not(MessageTemplate t) {
        Objects.requireNonNull(t, "template");
        return m -> !t.match(m);
    }

    static MessageTemplate matchPerformative(Performative p) {
        return m -> m.getPerformative() == p;
    }

    /** Matches on the sender's name (ignoring case, as AID equality does). */
    static MessageTemplate matchSender(AID sender) {
        return m -> sender.equals(m.getSender());
    }

    /** Matches messages that list the given agent among their receivers. */
    static MessageTemplate matchReceiver(AID receiver) {
        return m -> m.getReceivers().contains(receiver);
    }

    static MessageTemplate matchConversationId(String id) {
        return m -> Objects.equals(id, m.getConversationId());
    }

    static MessageTemplate matchInReplyTo(String id) {
        return m -> Objects.equals(id, m.getInReplyTo());
    }

    static MessageTemplate matchReplyWith(String id) {
        return m -> Objects.equals(id, m.getReplyWith());
    }

    static MessageTemplate matchProtocol(String protocol) {
        return m -> Objects.equals(protocol, m.getProtocol());
    }

    static MessageTemplate matchOntology(String ontology) {
        return m -> Objects.equals(ontology, m.getOntology());
    }

    static MessageTemplate matchLanguage(String language) {
        return m -> Objects.equals(language, m.getLanguage());
    }

    static MessageTemplate matchEncoding(String encoding) {
        return m -> Objects.equals(encoding, m.getEncoding());
    }

    static MessageTemplate matchContent(String content) {
        return m -> Objects.equals(content, m.getContent());
    }

    /** Matches on a predicate of your own. */
    static MessageTemplate matchCustom(Predicate<AclMessage> predicate) {
        Objects.requireNonNull(predicate, "predicate");
        return predicate::test;
    }
}
