package jade.proto.states;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * JADE's behaviour that waits for one message a template matches, until a deadline (an absolute
 * time in ms, or {@link #INFINITE}): it puts the message in the data store under its key, calls
 * {@link #handleMessage} (with null on timeout), and ends with the message's performative,
 * {@link #TIMEOUT_EXPIRED} or {@link #INTERRUPTED} as its {@link #onEnd()} value.
 */
public class MsgReceiver extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;
    public static final int TIMEOUT_EXPIRED = -1001;
    public static final int INTERRUPTED = -1002;
    public static final int INFINITE = -1;

    protected MessageTemplate template;
    protected long deadline;
    protected Object receivedMsgKey;
    private boolean received;
    private boolean interrupted;
    private int ret;

    public MsgReceiver(Agent a, MessageTemplate mt, long deadline, DataStore s, Object msgKey) {
        super(a);
        this.template = mt;
        this.deadline = deadline;
        this.receivedMsgKey = msgKey;
        setDataStore(s == null ? new DataStore() : s);
    }

    protected MsgReceiver() {
        super();
        setDataStore(new DataStore());
    }

    @Override
    public void action() {
        if (interrupted) {
            ret = INTERRUPTED;
            received = true;
            handleMessage(null);
            return;
        }
        ACLMessage m = myAgent.receive(template);
        if (m != null) {
            getDataStore().put(receivedMsgKey, m);
            received = true;
            ret = m.getPerformative();
            handleMessage(m);
            return;
        }
        if (deadline != INFINITE) {
            long left = deadline - System.currentTimeMillis();
            if (left <= 0) {
                getDataStore().put(receivedMsgKey, null);
                received = true;
                ret = TIMEOUT_EXPIRED;
                handleMessage(null);
            } else {
                block(left);
            }
        } else {
            block();
        }
    }

    @Override
    public boolean done() {
        return received;
    }

    /** The received message's performative, or {@link #TIMEOUT_EXPIRED} or {@link #INTERRUPTED}. */
    @Override
    public int onEnd() {
        return ret;
    }

    /** Called with the message received, or null on timeout or interruption. The default does nothing. */
    protected void handleMessage(ACLMessage msg) {
        // JADE's documented default: nothing (subclasses act on the message).
    }

    public void reset(MessageTemplate mt, long deadline, DataStore s, Object msgKey) {
        reset();
        this.template = mt;
        this.deadline = deadline;
        setDataStore(s);
        this.receivedMsgKey = msgKey;
    }

    @Override
    public void reset() {
        super.reset();
        received = false;
        interrupted = false;
        ret = 0;
    }

    public void setDeadline(long deadline) {
        this.deadline = deadline;
    }

    public void setTemplate(MessageTemplate mt) {
        this.template = mt;
    }

    public void setReceivedKey(Object key) {
        this.receivedMsgKey = key;
    }

    /** Ends the wait at once: {@link #onEnd()} returns {@link #INTERRUPTED}. */
    public void interrupt() {
        interrupted = true;
        restart();
    }
}
