package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.SequentialBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

import java.util.HashSet;
import java.util.Set;

/**
 * JADE's dispatcher of single-session responders: each message the template matches that opens
 * a new conversation (a conversation id no responder of its serves now) gets a responder of its
 * own ({@link #createResponder}), added to the agent by {@link #addBehaviour}; the messages of a
 * conversation being served are left to its responder.
 */
public abstract class SSResponderDispatcher extends CyclicBehaviour {
    private static final long serialVersionUID = 1L;
    private final Set<String> active = new HashSet<>();
    private final MessageTemplate template;

    public SSResponderDispatcher(Agent a, MessageTemplate tpl) {
        super(a);
        this.template = MessageTemplate.and(tpl,
                new MessageTemplate(m -> m.getConversationId() == null || !active.contains(m.getConversationId())));
    }

    @Override
    public final void action() {
        ACLMessage m = myAgent.receive(template);
        if (m == null) {
            block();
            return;
        }
        Behaviour responder = createResponder(m);
        if (responder == null) {
            return;
        }
        String conv = m.getConversationId();
        if (conv == null) {
            addBehaviour(responder);
            return;
        }
        active.add(conv);
        SequentialBehaviour session = new SequentialBehaviour(myAgent);
        session.addSubBehaviour(responder);
        session.addSubBehaviour(new OneShotBehaviour(myAgent) {
            private static final long serialVersionUID = 1L;

            @Override
            public void action() {
                active.remove(conv);
            }
        });
        addBehaviour(session);
    }

    /** The responder of the conversation this message opens (null: none). */
    protected abstract Behaviour createResponder(ACLMessage initiationMsg);

    /** Adds a responder to the agent. */
    protected void addBehaviour(Behaviour b) {
        myAgent.addBehaviour(b);
    }
}
