package io.concord.bench.concord;

import io.concord.bench.support.Rounds;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

import java.util.concurrent.atomic.AtomicLong;

/** A link of the chain on Concord, with exactly the rules of the JADE version. */
public class ConcordChainLink extends Agent {
    private final Rounds rounds;
    private final boolean first;
    private final String secret;
    /** Set once every link has started. */
    public volatile AID next;
    /**
     * The link before this one, if set: a message from anyone else is not passed on but counted
     * in {@link #strangers} (the attack benchmark's forged deliveries).
     */
    public volatile AID previous;
    public final AtomicLong strangers = new AtomicLong();
    /** The last message from a stranger, for the report: who sent what. */
    public volatile String lastStranger;

    public ConcordChainLink(Rounds rounds, boolean first, String secret) {
        this.rounds = rounds;
        this.first = first;
        this.secret = secret;
    }

    /** Starts a round; call on the runtime's loop. */
    public void startRound() {
        pass(secret);
    }

    private void pass(String content) {
        send(new AclMessage(Performative.INFORM).addReceiver(next).setContent(content));
    }

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                AclMessage m = receive();
                if (m == null) {
                    block();
                    return;
                }
                AID from = previous;
                if (from != null && !from.equals(m.getSender())) {
                    strangers.incrementAndGet();
                    lastStranger = m.getPerformative().wireName() + " from " + (m.getSender() == null ? "nobody" : m.getSender().name())
                            + " (" + m.getOntology() + ")";
                } else if (!first) {
                    pass(m.getContent());
                } else if (!secret.equals(m.getContent())) {
                    rounds.fail("the secret came back changed");
                } else if (rounds.roundDone()) {
                    pass(secret);
                }
            }
        });
    }
}
