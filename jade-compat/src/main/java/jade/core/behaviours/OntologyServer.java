package jade.core.behaviours;

import jade.content.ContentElement;
import jade.content.ContentException;
import jade.content.lang.Codec;
import jade.content.onto.Ontology;
import jade.content.onto.basic.Action;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.util.Logger;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.HashSet;
import java.util.Set;

/**
 * JADE's server of an ontology's actions and predicates: it receives the messages of that
 * ontology with one of the given performatives, extracts their content, and calls the server
 * delegate's (by default the OntologyServer's own: a subclass's) public method {@code serve<Element><Performative>(element, message)},
 * the element's simple class name and the performative in camel case ({@code serveSellRequest(Sell, ACLMessage)},
 * {@code serveOwnsQueryIf(Owns, ACLMessage)}); for an {@code Action}, the element is its action.
 * As JADE's: content it cannot read is answered NOT_UNDERSTOOD, an element no method serves
 * REFUSE {@code ((unsupported-act Element))}, a method that throws FAILURE
 * {@code ((internal-error "..."))}, each only for a performative that requires a reply
 * (REQUEST, QUERY_IF, QUERY_REF, CFP, PROPOSE, SUBSCRIBE, REQUEST_WHEN, REQUEST_WHENEVER unless changed).
 */
public class OntologyServer extends CyclicBehaviour {
    private static final long serialVersionUID = 1L;
    private static final int[] REPLY_NEEDED = {ACLMessage.REQUEST, ACLMessage.QUERY_IF, ACLMessage.QUERY_REF, ACLMessage.CFP,
        ACLMessage.PROPOSE, ACLMessage.SUBSCRIBE, ACLMessage.REQUEST_WHEN, ACLMessage.REQUEST_WHENEVER};

    protected Logger myLogger = Logger.getMyLogger(getClass().getName());
    private final Ontology onto;
    private final int[] performatives;
    private final Object serverDelegate;
    private final Set<Integer> replyNeeded = new HashSet<>();
    private final Set<String> ignored = new HashSet<>();
    private Codec codec;
    private MessageTemplate template;
    private MessageTemplate extra;
    private ContentElement received;

    public OntologyServer(Agent a, Ontology onto, int performative) {
        this(a, onto, new int[] {performative}, null);
    }

    public OntologyServer(Agent a, Ontology onto, int[] performatives) {
        this(a, onto, performatives, null);
    }

    public OntologyServer(Agent a, Ontology onto, int performative, Object serverDelegate) {
        this(a, onto, new int[] {performative}, serverDelegate);
    }

    public OntologyServer(Agent a, Ontology onto, int[] performatives, Object serverDelegate) {
        super(a);
        this.onto = onto;
        this.performatives = performatives.clone();
        this.serverDelegate = serverDelegate != null ? serverDelegate : this;
        for (int p : REPLY_NEEDED) {
            replyNeeded.add(p);
        }
    }

    /** The content language to register if the agent has none of that name (the default: SL). */
    public void setLanguage(Codec codec) {
        this.codec = codec;
    }

    /** A further condition on the messages served. */
    public void setMessageTemplate(MessageTemplate mt) {
        this.extra = mt;
        template = null;
    }

    public void addPerformativeRequiringReply(int performative) {
        replyNeeded.add(performative);
    }

    public void removePerformativeRequiringReply(int performative) {
        replyNeeded.remove(performative);
    }

    /** Leaves the messages of that conversation to another behaviour. */
    public void ignoreConversation(String convId) {
        ignored.add(convId);
    }

    /** Serves that conversation's messages again. */
    public void conversationFinished(String convId) {
        ignored.remove(convId);
    }

    /** Registers the ontology (and SL, or the language set) with the agent's content manager if it does not have them. */
    @Override
    public void onStart() {
        jade.content.ContentManager cm = myAgent.getContentManager();
        if (cm.lookupOntology(onto.getName()) == null) {
            cm.registerOntology(onto);
        }
        Codec c = codec != null ? codec : new jade.content.lang.sl.SLCodec();
        if (cm.lookupLanguage(c.getName()) == null) {
            cm.registerLanguage(c);
        }
    }

    private MessageTemplate template() {
        if (template == null) {
            MessageTemplate perf = null;
            for (int p : performatives) {
                MessageTemplate one = MessageTemplate.MatchPerformative(p);
                perf = perf == null ? one : MessageTemplate.or(perf, one);
            }
            MessageTemplate t = MessageTemplate.and(MessageTemplate.MatchOntology(onto.getName()), perf);
            t = MessageTemplate.and(t, new MessageTemplate(m -> m.getConversationId() == null || !ignored.contains(m.getConversationId())));
            template = extra == null ? t : MessageTemplate.and(t, extra);
        }
        return template;
    }

    @Override
    public final void action() {
        ACLMessage m = myAgent.receive(template());
        if (m == null) {
            block();
            return;
        }
        handleMessage(m);
    }

    /** Extracts the content and serves it (see the class comment). */
    protected void handleMessage(ACLMessage msg) {
        Object key = null;
        try {
            received = myAgent.getContentManager().extractContent(msg);
            key = extractKeyContentElement(received);
            Method serve = serveMethod(key, msg.getPerformative());
            if (serve == null) {
                handleUnsupported(key, msg);
                return;
            }
            serve.invoke(serverDelegate, key, msg);
        } catch (ContentException e) {
            handleNotUnderstood(e, msg);
        } catch (InvocationTargetException e) {
            handleServingFailure(e.getCause(), key, msg);
        } catch (IllegalAccessException e) {
            handleServingFailure(e, key, msg);
        }
    }

    private Method serveMethod(Object key, int performative) {
        String perf = camel(ACLMessage.getPerformative(performative));
        String name = "serve" + key.getClass().getSimpleName() + perf;
        for (Method m : serverDelegate.getClass().getMethods()) {
            if (m.getName().equals(name) && m.getParameterCount() == 2 && m.getParameterTypes()[0].isInstance(key)
                    && m.getParameterTypes()[1] == ACLMessage.class) {
                return m;
            }
        }
        return null;
    }

    /** {@code QUERY-IF} as {@code QueryIf}. */
    private static String camel(String performative) {
        StringBuilder b = new StringBuilder();
        boolean upper = true;
        for (char ch : performative.toCharArray()) {
            if (ch == '-' || ch == '_') {
                upper = true;
                continue;
            }
            b.append(upper ? Character.toUpperCase(ch) : Character.toLowerCase(ch));
            upper = false;
        }
        return b.toString();
    }

    /** The content element the message being served carried. */
    public final ContentElement getReceivedContentElement() {
        return received;
    }

    /** What the serve method is chosen by: an action's action, else the element. */
    protected Object extractKeyContentElement(ContentElement ce) {
        return ce instanceof Action a ? a.getAction() : ce;
    }

    /** No method serves the element: REFUSE {@code ((unsupported-act Element))} if the performative requires a reply. */
    protected void handleUnsupported(Object keyCel, ACLMessage msg) {
        myLogger.log(Logger.WARNING, "Agent " + myAgent.getName() + " - Unsupported content-element " + keyCel.getClass().getSimpleName()
                + ". Sender is " + (msg.getSender() == null ? null : msg.getSender().getName()));
        reply(msg, ACLMessage.REFUSE, "((unsupported-act " + keyCel.getClass().getSimpleName() + "))");
    }

    /** The serve method threw: FAILURE {@code ((internal-error "..."))} if the performative requires a reply. */
    protected void handleServingFailure(Throwable t, Object keyCel, ACLMessage msg) {
        myLogger.log(Logger.SEVERE, "Agent " + myAgent.getName() + " - Error serving " + ACLMessage.getPerformative(msg.getPerformative())
                + " message", t);
        reply(msg, ACLMessage.FAILURE, "((internal-error \"" + String.valueOf(t).replace("\"", "'") + "\"))");
    }

    /** The content could not be read: NOT_UNDERSTOOD if the performative requires a reply. */
    protected void handleNotUnderstood(ContentException ce, ACLMessage msg) {
        myLogger.log(Logger.WARNING, "Agent " + myAgent.getName() + " - Error decoding " + ACLMessage.getPerformative(msg.getPerformative())
                + " message. Sender is " + (msg.getSender() == null ? null : msg.getSender().getName()), ce);
        reply(msg, ACLMessage.NOT_UNDERSTOOD, null);
    }

    private void reply(ACLMessage msg, int performative, String content) {
        if (!replyNeeded.contains(msg.getPerformative())) {
            return;
        }
        ACLMessage r = msg.createReply();
        r.setPerformative(performative);
        if (content != null) {
            r.setContent(content);
        }
        myAgent.send(r);
    }
}
