package io.concord.jadecompat.internal;

import io.concord.core.acl.AclMessage;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

import java.util.function.Consumer;

/**
 * The Concord agent under a JADE agent: it holds the JADE agent's name, port and stack on
 * Concord's loop, and hands each message it receives to the JADE agent's own thread. It does no
 * work of its own, so the loop is never held by JADE code.
 */
public final class Host extends Agent {
    private final Consumer<AclMessage> sink;

    /** A host that passes each received message to {@code sink} (on the loop; the sink must not block). */
    public Host(Consumer<AclMessage> sink) {
        this.sink = sink;
    }

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                AclMessage m;
                while ((m = myAgent.receive()) != null) {
                    sink.accept(m);
                }
                block();
            }
        });
    }
}
