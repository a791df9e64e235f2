package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.TickerBehaviour;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Under 20% loss, 10% duplication, 10% reordering and 2% corruption together, 10,000 messages
 * from one agent to another arrive exactly once, in order, unchanged.
 */
class NothingLostTest {
    static final int MESSAGES = 10_000;

    /** Sends numbered messages, a batch every millisecond. */
    static final class Sender extends Agent {
        private final AID to;
        private final int total;
        int sent;

        Sender(AID to, int total) {
            this.to = to;
            this.total = total;
        }

        @Override
        protected void setup() {
            addBehaviour(new TickerBehaviour(this, 1) {
                @Override
                protected void onTick() {
                    for (int i = 0; i < 20 && sent < total; i++) {
                        send(new AclMessage(Performative.INFORM).addReceiver(to).setContent(content(sent++)));
                    }
                    if (sent == total) {
                        stop();
                    }
                }
            });
        }
    }

    static String content(int i) {
        return "message " + i + " " + "x".repeat(i % 200);
    }

    @ParameterizedTest
    @EnumSource(Profile.class)
    void tenThousandMessagesArriveExactlyOnceInOrderUnchanged(Profile profile) {
        try (Simulation sim = new Simulation(2024, FaultPlan.lossy(0.20, 0.10, 0.10, 0.02))) {
            AgentRuntime a = sim.newRuntime("host-a", Stacks.of(profile));
            AgentRuntime b = sim.newRuntime("host-b", Stacks.of(profile));
            ThreatWorld.Receiver receiver = new ThreatWorld.Receiver();
            AID to = b.startAgent("receiver", receiver);
            Sender sender = new Sender(to, MESSAGES);
            a.startAgent("sender", sender);
            boolean done = sim.runUntil(() -> receiver.got.size() >= MESSAGES, 600_000);
            sim.runFor(2_000); // anything late would show up as an extra
            assertTrue(done, "only " + receiver.got.size() + " of " + MESSAGES + " arrived (seed " + sim.seed()
                    + "); drops at the receiver: " + b.drops());
            assertEquals(MESSAGES, receiver.got.size(), "exactly once");
            List<AclMessage> got = List.copyOf(receiver.got);
            for (int i = 0; i < MESSAGES; i++) {
                assertEquals(content(i), got.get(i).getContent(), "message " + i + " in order and unchanged");
            }
            var drops = b.drops();
            assertTrue(drops.getOrDefault("bad-tag", 0L) + drops.getOrDefault("corrupt", 0L) > 0,
                    "corrupted frames were caught: " + drops);
            assertTrue(drops.getOrDefault("repeated", 0L) + drops.getOrDefault("copy", 0L) > 0,
                    "duplicates were filtered: " + drops);
        }
    }
}
