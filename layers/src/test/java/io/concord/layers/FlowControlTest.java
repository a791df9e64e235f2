package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.agent.TickerBehaviour;
import io.concord.core.layer.SendRejectedException;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.sequence.SequenceLayer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A sender far faster than its receiver (class 7, on the test kit's network): nothing is lost,
 * the receiver's mailbox stays within its capacity, and the sender is slowed to the receiver's
 * pace; an agent that sends more in one action than the platform will hold is told, by an
 * exception naming {@code flow-control}, and loses nothing it was not told of.
 */
public class FlowControlTest {
    private static final int CAPACITY = 1_000;

    /**
     * Sends numbered messages ({@code m0}, {@code m1}...), 100 (or {@code batch}) in each action of
     * a cyclic behaviour, as fast as it is let. Also HandOverTest's.
     */
    public static final class FastSender extends Agent {
        private final AID to;
        private final int total;
        private final int batch;
        int sent;

        FastSender(AID to, int total) {
            this(to, total, 100);
        }

        public FastSender(AID to, int total, int batch) {
            this.to = to;
            this.total = total;
            this.batch = batch;
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    for (int i = 0; i < batch && sent < total; i++) {
                        send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("m" + sent++));
                    }
                    if (sent == total) {
                        myAgent.removeBehaviour(this);
                    }
                }
            });
        }
    }

    /** Takes 5 messages a millisecond: 100 times slower than the sender offers them. */
    static final class SlowReceiver extends Agent {
        final List<String> got = new ArrayList<>();
        int mostWaiting;

        @Override
        protected void setup() {
            addBehaviour(new TickerBehaviour(this, 1) {
                @Override
                protected void onTick() {
                    mostWaiting = Math.max(mostWaiting, getCurQueueSize());
                    AclMessage m;
                    for (int i = 0; i < 5 && (m = receive()) != null; i++) {
                        got.add(m.getContent());
                    }
                }
            });
        }
    }

    @ParameterizedTest
    @ValueSource(doubles = {0.0, 0.05})
    void aSlowReceiverSlowsAFastSenderAndNothingIsLost(double loss) {
        int total = 10_000;
        try (Simulation sim = new Simulation(19, loss == 0 ? FaultPlan.NONE : FaultPlan.lossy(loss, loss, loss, 0))) {
            AgentRuntime a = sim.newRuntime("host-a", Stacks.of(Profile.CLASS_7));
            AgentRuntime b = sim.newRuntime("host-b", Stacks.of(Profile.CLASS_7), r -> r.mailboxCapacity(CAPACITY));
            SlowReceiver receiver = new SlowReceiver();
            AID to = b.startAgent("receiver", receiver);
            a.startAgent("sender", new FastSender(to, total));
            boolean done = sim.runUntil(() -> receiver.got.size() >= total, 600_000);
            sim.runFor(1_000);
            assertTrue(done, "only " + receiver.got.size() + " of " + total + " arrived; drops at the receiver: " + b.drops()
                    + ", at the sender: " + a.drops());
            assertEquals(total, receiver.got.size(), "exactly once");
            for (int i = 0; i < total; i++) {
                assertEquals("m" + i, receiver.got.get(i), "in order");
            }
            assertEquals(0L, b.drops().getOrDefault("mailbox-full", 0L), "the mailbox never overflowed: " + b.drops());
            assertEquals(0L, b.drops().getOrDefault("lost", 0L) + a.drops().getOrDefault("lost", 0L));
            assertTrue(receiver.mostWaiting <= CAPACITY, "at most " + receiver.mostWaiting + " waiting");
            assertTrue(a.pauses() > 0, "the sender was paused while the receiver caught up");
            // Under loss the receiver asks for a gap when it opens, not again at every frame after
            // it (that made the sender resend a window per frame: 1.56 million repeats here).
            long repeated = b.drops().getOrDefault("repeated", 0L);
            assertTrue(repeated < 10L * total, repeated + " frames were sent again and again: " + b.drops());
        }
    }

    @Test
    void aSenderThatSendsMoreInOneActionThanIsHeldIsToldAndLosesNothingElse() {
        int tryToSend = 256 + SequenceLayer.MAX_HELD + 500;
        try (Simulation sim = new Simulation(20, FaultPlan.NONE)) {
            AgentRuntime a = sim.newRuntime("host-a", Stacks.of(Profile.CLASS_7));
            AgentRuntime b = sim.newRuntime("host-b", Stacks.of(Profile.CLASS_7));
            ThreatWorld.Receiver receiver = new ThreatWorld.Receiver();
            AID to = b.startAgent("receiver", receiver);
            List<SendRejectedException> told = new ArrayList<>();
            int[] accepted = {0};
            a.startAgent("sender", new Agent() {
                @Override
                protected void setup() {
                    addBehaviour(new OneShotBehaviour(this) {
                        @Override
                        public void action() {
                            for (int i = 0; i < tryToSend; i++) {
                                try {
                                    send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("m" + i));
                                    accepted[0]++;
                                } catch (SendRejectedException e) {
                                    told.add(e);
                                    return;
                                }
                            }
                        }
                    });
                }
            });
            sim.runUntil(() -> !told.isEmpty() && receiver.got.size() >= accepted[0], 600_000);
            sim.runFor(1_000);
            assertEquals(1, told.size(), "the sender was told once, and stopped");
            assertEquals("flow-control", told.get(0).reason());
            assertTrue(told.get(0).getMessage().contains("send fewer in one action"), told.get(0).getMessage());
            assertEquals(256 + SequenceLayer.MAX_HELD, accepted[0], "the window and the held frames, then no more");
            assertEquals(accepted[0], receiver.got.size(), "everything accepted arrived");
            List<AclMessage> got = List.copyOf(receiver.got);
            for (int i = 0; i < accepted[0]; i++) {
                assertEquals("m" + i, got.get(i).getContent());
            }
            assertEquals(1L, a.drops().getOrDefault("flow-control", 0L), "the refusal was counted: " + a.drops());
        }
    }
}
