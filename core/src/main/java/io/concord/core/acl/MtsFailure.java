package io.concord.core.acl;

/**
 * The FAILURE a platform's AMS sends when a message cannot be delivered, written as JADE's AMS
 * writes it, so that JADE and Concord protocols alike end instead of waiting.
 */
public final class MtsFailure {
    private MtsFailure() {
    }

    /**
     * @param platform the platform whose {@code ams} answers
     * @param original the message that could not be delivered (its sender gets the FAILURE)
     * @param receiver the receiver it could not reach
     * @param reason   what went wrong, e.g. {@code Agent not found: bob@plat}
     */
    public static AclMessage of(String platform, AclMessage original, AID receiver, String reason) {
        AclMessage f = new AclMessage(Performative.FAILURE);
        f.setSender(AID.local("ams", platform));
        f.addReceiver(original.getSender());
        f.setConversationId(original.getConversationId());
        f.setInReplyTo(original.getReplyWith());
        f.setProtocol(original.getProtocol());
        f.setLanguage("fipa-sl");
        f.setContent("( (action ( agent-identifier :name " + original.getSender().name() + " ) (ACLMessage) ) (MTS-error "
                + "( agent-identifier :name " + receiver.name() + " ) (internal-error \"" + reason.replace("\"", "'")
                + "\")) )");
        return f;
    }
}
