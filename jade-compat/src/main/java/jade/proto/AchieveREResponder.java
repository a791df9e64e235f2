package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * JADE's responder of FIPA-request-like protocols: for each message the template matches, it
 * calls {@link #handleRequest} (by default {@link #prepareResponse}) and sends what it returns
 * (AGREE, REFUSE, NOT_UNDERSTOOD; exceptions become REFUSE or NOT_UNDERSTOOD); after an AGREE,
 * or when it returned null, it calls {@link #prepareResultNotification} and sends its INFORM or
 * FAILURE (a {@link FailureException} becomes a FAILURE). It never ends.
 */
public class AchieveREResponder extends SimpleBehaviour implements FIPANames.InteractionProtocol {
    private static final long serialVersionUID = 1L;

    /** Data store keys, as JADE names them. */
    public final String REQUEST_KEY = "__request" + hashCode();
    public final String RESPONSE_KEY = "__response" + hashCode();
    public final String RESULT_NOTIFICATION_KEY = "__result-notification" + hashCode();

    private MessageTemplate template;
    private Behaviour requestStep;
    private Behaviour resultStep;

    /** A template for the requests of a protocol: its name and its first performative(s). */
    public static MessageTemplate createMessageTemplate(String iprotocol) {
        MessageTemplate proto = MessageTemplate.MatchProtocol(iprotocol);
        if (FIPA_QUERY.equals(iprotocol)) {
            return MessageTemplate.and(proto, MessageTemplate.or(MessageTemplate.MatchPerformative(ACLMessage.QUERY_IF),
                    MessageTemplate.MatchPerformative(ACLMessage.QUERY_REF)));
        }
        if (FIPA_REQUEST_WHEN.equals(iprotocol)) {
            return MessageTemplate.and(proto, MessageTemplate.MatchPerformative(ACLMessage.REQUEST_WHEN));
        }
        if (FIPA_REQUEST.equals(iprotocol)) {
            return MessageTemplate.and(proto, MessageTemplate.MatchPerformative(ACLMessage.REQUEST));
        }
        return proto;
    }

    public AchieveREResponder(Agent a, MessageTemplate mt) {
        this(a, mt, new DataStore());
    }

    public AchieveREResponder(Agent a, MessageTemplate mt, DataStore store) {
        super(a);
        this.template = mt;
        setDataStore(store);
    }

    @Override
    public void action() {
        ACLMessage request = myAgent.receive(template);
        if (request == null) {
            block();
            return;
        }
        getDataStore().put(REQUEST_KEY, request);
        ACLMessage response;
        if (States.run(this, requestStep, getDataStore(), RESPONSE_KEY)) {
            response = (ACLMessage) getDataStore().get(RESPONSE_KEY);
        } else {
            response = Replies.answer(request, () -> handleRequest(request), ACLMessage.NOT_UNDERSTOOD, ACLMessage.REFUSE);
            getDataStore().put(RESPONSE_KEY, response);
        }
        Replies.send(myAgent, response, request);
        if (response == null || response.getPerformative() == ACLMessage.AGREE) {
            ACLMessage result;
            if (States.run(this, resultStep, getDataStore(), RESULT_NOTIFICATION_KEY)) {
                result = (ACLMessage) getDataStore().get(RESULT_NOTIFICATION_KEY);
            } else {
                result = Replies.answer(request, () -> prepareResultNotification(request, response), ACLMessage.FAILURE);
                getDataStore().put(RESULT_NOTIFICATION_KEY, result);
            }
            Replies.send(myAgent, result, request);
        }
    }

    /** Never ends. */
    @Override
    public boolean done() {
        return false;
    }

    /**
     * The answer to a request: AGREE, REFUSE, NOT_UNDERSTOOD, or null to go straight to the
     * result. Override this one. If it is not overridden, it prints
     * {@code prepareResponse() method not re-defined} on standard output, as JADE 4.3 does, and
     * returns null.
     */
    protected ACLMessage prepareResponse(ACLMessage request) throws NotUnderstoodException, RefuseException {
        System.out.println("prepareResponse() method not re-defined");
        return null;
    }

    /** JADE's older name for {@link #prepareResponse}: what the responder calls; by default {@link #prepareResponse}'s answer. */
    protected ACLMessage handleRequest(ACLMessage request) throws NotUnderstoodException, RefuseException {
        return prepareResponse(request);
    }

    /**
     * The result after an AGREE (or no answer): INFORM or FAILURE, or null to send none. If it is
     * not overridden, it prints {@code prepareResultNotification() method not re-defined}, as
     * JADE 4.3 does, and returns null.
     */
    protected ACLMessage prepareResultNotification(ACLMessage request, ACLMessage response) throws FailureException {
        System.out.println("prepareResultNotification() method not re-defined");
        return null;
    }

    /**
     * Puts a behaviour in place of {@link #handleRequest}/{@link #prepareResponse}: it reads the
     * request under {@link #REQUEST_KEY} and puts its answer (or nothing) under {@link #RESPONSE_KEY}
     * of the data store it is given. It runs on the spot, to its end, for each request.
     */
    public void registerHandleRequest(Behaviour b) {
        requestStep = b;
    }

    /** As {@link #registerHandleRequest} (JADE's two names for the one step). */
    public void registerPrepareResponse(Behaviour b) {
        registerHandleRequest(b);
    }

    /**
     * Puts a behaviour in place of {@link #prepareResultNotification}: it reads
     * {@link #REQUEST_KEY} and {@link #RESPONSE_KEY} and puts the result under
     * {@link #RESULT_NOTIFICATION_KEY}. It runs on the spot, to its end, after each AGREE (or no answer).
     */
    public void registerPrepareResultNotification(Behaviour b) {
        resultStep = b;
    }

    /** Serves another template from now on. */
    public void reset(MessageTemplate mt) {
        this.template = mt;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
    }
}
