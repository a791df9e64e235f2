package io.concord.testkit;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.TickerBehaviour;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A thousand agents in one JVM on the virtual network: each ticks at a random period and gossips
 * to random peers, who answer. Same seed, same trace, message for message.
 */
class DeterminismTest {
    private static final int AGENTS = 1_000;

    /** Gossips to random peers on a ticker, answers every message it gets with a CONFIRM. */
    static final class Gossip extends Agent {
        private final List<AID> peers;
        int received;

        Gossip(List<AID> peers) {
            this.peers = peers;
        }

        @Override
        protected void setup() {
            long period = 50 + random().nextInt(200);
            addBehaviour(new TickerBehaviour(this, period) {
                @Override
                protected void onTick() {
                    AclMessage m = new AclMessage(Performative.INFORM);
                    m.addReceiver(peers.get(random().nextInt(peers.size())));
                    m.setConversationId(newConversationId());
                    m.setContent("rumour " + random().nextInt(1_000_000));
                    send(m);
                    if (getTickCount() == 10) {
                        stop();
                    }
                }
            });
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m = receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    received++;
                    if (m.getPerformative() == Performative.INFORM) {
                        AclMessage r = m.createReply();
                        r.setPerformative(Performative.CONFIRM);
                        send(r);
                    }
                }
            });
        }
    }

    private record Outcome(long hash, long events, long received, long dropped) {
    }

    private Outcome run(long seed) {
        try (Simulation sim = new Simulation(seed, FaultPlan.lossy(0.05, 0.02, 0.05, 0.01))) {
            AgentRuntime rt = sim.newRuntime("host");
            List<AID> peers = new ArrayList<>();
            List<Gossip> agents = new ArrayList<>();
            for (int i = 0; i < AGENTS; i++) {
                Gossip g = new Gossip(peers);
                agents.add(g);
                peers.add(rt.startAgent("g" + i, g));
            }
            sim.runFor(10_000);
            long received = agents.stream().mapToLong(g -> g.received).sum();
            return new Outcome(sim.trace().hash(), sim.trace().count(), received, rt.drops().getOrDefault("malformed", 0L));
        }
    }

    @Test
    void theSameSeedGivesTheSameTraceForAThousandAgents() {
        Outcome first = run(1234);
        Outcome second = run(1234);
        assertEquals(first, second, "seed 1234 replayed differently");
        assertTrue(first.received() > AGENTS * 10, "messages flowed: " + first.received());
        assertTrue(first.dropped() > 0, "corrupted datagrams were dropped as malformed, not delivered");
        Outcome other = run(4321);
        assertNotEquals(first.hash(), other.hash(), "another seed gives another run");
    }
}
