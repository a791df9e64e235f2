package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.lang.acl.MessageTemplate;

/**
 * JADE's simpler responder of FIPA-request-like protocols: {@code prepareResponse} and
 * {@code prepareResultNotification}, as {@link AchieveREResponder}, which this is written over
 * (so it is also an {@code AchieveREResponder} here, where JADE's is a plain {@code SimpleBehaviour}).
 */
public class SimpleAchieveREResponder extends AchieveREResponder {
    private static final long serialVersionUID = 1L;

    /** A template for the requests of a protocol: its name and its first performative(s). */
    public static MessageTemplate createMessageTemplate(String iprotocol) {
        return AchieveREResponder.createMessageTemplate(iprotocol);
    }

    public SimpleAchieveREResponder(Agent a, MessageTemplate mt) {
        super(a, mt);
    }

    public SimpleAchieveREResponder(Agent a, MessageTemplate mt, DataStore store) {
        super(a, mt, store);
    }
}
