package io.concord.core.agent;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;

import java.util.function.Consumer;

/** Handing every message a template matches to a handler, on the agent's loop. */
public final class Inbox {
    private Inbox() {
    }

    /** Adds a behaviour that gives each message {@code template} matches to {@code handler}. */
    public static Behaviour each(Agent agent, MessageTemplate template, Consumer<AclMessage> handler) {
        Behaviour b = new CyclicBehaviour(agent) {
            @Override
            public void action() {
                AclMessage m = myAgent.receive(template);
                if (m == null) {
                    block();
                    return;
                }
                handler.accept(m);
            }
        };
        agent.addBehaviour(b);
        return b;
    }
}
