package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.lang.acl.ACLMessage;

import java.util.Vector;

/**
 * JADE's simpler initiator of FIPA-request-like protocols: one request (made by
 * {@link #prepareRequest}), the same handlers as {@link AchieveREInitiator}, which this is
 * written over (so it is also an {@code AchieveREInitiator} here, where JADE's is a plain
 * {@code SimpleBehaviour}).
 */
@SuppressWarnings({"rawtypes", "unchecked"})
public class SimpleAchieveREInitiator extends AchieveREInitiator {
    private static final long serialVersionUID = 1L;

    public final String REQUEST_SENT_KEY = "__request-sent" + hashCode();
    public final String SECOND_REPLY_KEY = "__2nd-reply" + hashCode();

    public SimpleAchieveREInitiator(Agent a, ACLMessage msg) {
        super(a, msg);
    }

    public SimpleAchieveREInitiator(Agent a, ACLMessage msg, DataStore store) {
        super(a, msg, store);
    }

    /** The request to send (null: none); by default the message given to the constructor. */
    protected ACLMessage prepareRequest(ACLMessage msg) {
        return msg;
    }

    /** The one request {@link #prepareRequest} makes, put in the data store under {@link #REQUEST_SENT_KEY} too. */
    @Override
    protected final Vector prepareRequests(ACLMessage request) {
        ACLMessage m = prepareRequest(request);
        getDataStore().put(REQUEST_SENT_KEY, m);
        Vector v = new Vector(1);
        if (m != null) {
            v.add(m);
        }
        return v;
    }
}
