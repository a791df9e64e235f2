package io.concord.testkit;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

import java.util.function.Consumer;

/**
 * The peer most tests and benchmarks need: answers every REQUEST with an INFORM whose content is
 * the request's behind a prefix ({@code "echo:"} by default), and shows every message it gets to a
 * listener first. Subclasses may add behaviours in {@link #setup()} after calling it.
 */
public class EchoAgent extends Agent {
    private final String prefix;
    private final Consumer<AclMessage> seen;

    public EchoAgent() {
        this("echo:", m -> { });
    }

    /**
     * @param prefix put before the request's content in the answer
     * @param seen   called with every message the agent gets, on its loop, before it answers
     */
    public EchoAgent(String prefix, Consumer<AclMessage> seen) {
        this.prefix = prefix;
        this.seen = seen;
    }

    private volatile boolean deaf;

    /**
     * From now on it takes nothing from its mailbox: a receiver that has fallen behind, whose
     * mailbox fills and whose sequence layer then shuts its window to its senders. Any thread.
     */
    public void stopTaking() {
        deaf = true;
    }

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour() {
            @Override
            public void action() {
                if (deaf) {
                    block();
                    return;
                }
                AclMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                seen.accept(m);
                if (m.getPerformative() == Performative.REQUEST) {
                    AclMessage r = m.createReply();
                    r.setPerformative(Performative.INFORM);
                    r.setContent(prefix + m.getContent());
                    myAgent.send(r);
                }
            }
        });
    }
}
