package io.concord.core.agent;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Every kind of behaviour, with JADE's semantics, on virtual time. */
class BehaviourTest {
    private final Simulation sim = new Simulation(1, FaultPlan.NONE);
    private final AgentRuntime rt = sim.newRuntime("h1");
    private final List<String> log = new ArrayList<>();

    @AfterEach
    void close() {
        sim.close();
    }

    private long ms() {
        return sim.clock().nanoTime() / 1_000_000L;
    }

    private AID start(String name, java.util.function.Consumer<Agent> setup) {
        return rt.startAgent(name, new LambdaAgent(setup));
    }

    private void tell(AID to, String content) {
        start("teller" + log.size() + "-" + content.hashCode(), a -> a.addBehaviour(new OneShotBehaviour() {
            @Override
            public void action() {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(to);
                m.setContent(content);
                myAgent.send(m);
            }
        }));
    }

    @Test
    void aOneShotBehaviourRunsOnceAndEnds() {
        int[] runs = {0};
        start("a", a -> a.addBehaviour(new OneShotBehaviour() {
            @Override
            public void action() {
                runs[0]++;
            }

            @Override
            public int onEnd() {
                log.add("end");
                return 0;
            }
        }));
        sim.runUntilQuiet(1_000);
        assertEquals(1, runs[0]);
        assertEquals(List.of("end"), log);
    }

    @Test
    void aBlockedCyclicBehaviourRunsAgainOnlyWhenAMessageArrives() {
        int[] steps = {0};
        AID a = start("a", ag -> ag.addBehaviour(new CyclicBehaviour() {
            @Override
            public void action() {
                steps[0]++;
                AclMessage m = myAgent.receive();
                if (m == null) {
                    block();
                } else {
                    log.add(m.getContent());
                }
            }
        }));
        sim.runUntilQuiet(1_000);
        assertEquals(1, steps[0], "it blocked after its first empty step and was not run again");
        tell(a, "one");
        tell(a, "two");
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("one", "two"), log);
        assertTrue(steps[0] <= 5, "woken only by messages, ran " + steps[0] + " steps");
    }

    @Test
    void blockWithATimeoutRestartsTheBehaviourAfterIt() {
        List<Long> at = new ArrayList<>();
        start("a", ag -> ag.addBehaviour(new Behaviour() {
            @Override
            public void action() {
                at.add(ms());
                block(100);
            }

            @Override
            public boolean done() {
                return at.size() == 3;
            }
        }));
        sim.runUntilQuiet(10_000);
        assertEquals(List.of(0L, 100L, 200L), at);
    }

    @Test
    void aTickerTicksEveryPeriodUntilStopped() {
        List<Long> ticks = new ArrayList<>();
        start("a", ag -> ag.addBehaviour(new TickerBehaviour(ag, 250) {
            @Override
            protected void onTick() {
                ticks.add(ms());
                if (getTickCount() == 4) {
                    stop();
                }
            }
        }));
        sim.runFor(5_000);
        assertEquals(List.of(250L, 500L, 750L, 1000L), ticks);
    }

    @Test
    void aWakerWakesOnceAfterItsTimeout() {
        List<Long> woke = new ArrayList<>();
        start("a", ag -> ag.addBehaviour(new WakerBehaviour(ag, 1_500) {
            @Override
            protected void onWake() {
                woke.add(ms());
            }
        }));
        sim.runFor(5_000);
        assertEquals(List.of(1500L), woke);
    }

    @Test
    void aMessageWakesATickerEarlyButDoesNotMakeItTick() {
        List<Long> ticks = new ArrayList<>();
        AID a = start("a", ag -> ag.addBehaviour(new TickerBehaviour(ag, 1_000) {
            @Override
            protected void onTick() {
                ticks.add(ms());
                stop();
            }
        }));
        tell(a, "noise");
        sim.runFor(3_000);
        assertEquals(List.of(1000L), ticks);
    }

    @Test
    void aSequentialBehaviourRunsItsChildrenInOrderAndWaitsForABlockedOne() {
        AID a = start("a", ag -> {
            SequentialBehaviour seq = new SequentialBehaviour(ag);
            seq.addSubBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    log.add("first");
                }
            });
            seq.addSubBehaviour(new Behaviour() {
                private boolean got;

                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    log.add("got " + m.getContent());
                    got = true;
                }

                @Override
                public boolean done() {
                    return got;
                }
            });
            seq.addSubBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    log.add("last");
                }
            });
            ag.addBehaviour(seq);
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("first"), log);
        tell(a, "go");
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("first", "got go", "last"), log);
    }

    private Behaviour counting(String name, int steps) {
        return new Behaviour() {
            private int n;

            @Override
            public void action() {
                log.add(name + n++);
            }

            @Override
            public boolean done() {
                return n >= steps;
            }

            @Override
            public void reset() {
                super.reset();
                n = 0;
            }
        };
    }

    @Test
    void aParallelBehaviourInterleavesItsChildrenAndEndsWhenAllDo() {
        start("a", ag -> {
            ParallelBehaviour par = new ParallelBehaviour(ag, ParallelBehaviour.WHEN_ALL);
            par.addSubBehaviour(counting("x", 2));
            par.addSubBehaviour(counting("y", 3));
            ag.addBehaviour(new SequentialBehaviourOf(ag, par, () -> log.add("done")));
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("x0", "y0", "x1", "y1", "y2", "done"), log);
    }

    @Test
    void aParallelBehaviourWhenAnyEndsWithTheFirstChild() {
        start("a", ag -> {
            ParallelBehaviour par = new ParallelBehaviour(ag, ParallelBehaviour.WHEN_ANY);
            par.addSubBehaviour(counting("x", 1));
            par.addSubBehaviour(counting("y", 10));
            ag.addBehaviour(new SequentialBehaviourOf(ag, par, () -> log.add("done")));
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("x0", "done"), log);
    }

    /** A sequence of one behaviour and a final one-shot. */
    private static final class SequentialBehaviourOf extends SequentialBehaviour {
        SequentialBehaviourOf(Agent a, Behaviour first, Runnable then) {
            super(a);
            addSubBehaviour(first);
            addSubBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    then.run();
                }
            });
        }
    }

    @Test
    void anFsmFollowsItsTransitionsResetsWhatItIsToldAndEndsInALastState() {
        int[] visitsOfA = {0};
        start("a", ag -> {
            FSMBehaviour fsm = new FSMBehaviour(ag) {
                @Override
                public int onEnd() {
                    log.add("fsm exit " + getLastExitValue());
                    return super.onEnd();
                }
            };
            fsm.registerFirstState(new OneShotBehaviour() {
                @Override
                public void action() {
                    log.add("A");
                    visitsOfA[0]++;
                }

                @Override
                public int onEnd() {
                    return visitsOfA[0] < 3 ? 1 : 2;
                }
            }, "A");
            fsm.registerState(counting("B", 2), "B");
            fsm.registerLastState(new OneShotBehaviour() {
                @Override
                public void action() {
                    log.add("C");
                }

                @Override
                public int onEnd() {
                    return 7;
                }
            }, "C");
            fsm.registerTransition("A", "B", 1, new String[]{"B"});
            fsm.registerTransition("A", "C", 2);
            fsm.registerDefaultTransition("B", "A");
            ag.addBehaviour(fsm);
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("A", "B0", "B1", "A", "B0", "B1", "A", "C", "fsm exit 7"), log);
    }

    @Test
    void anFsmWithoutATransitionForAnExitValueStopsWithAClearError() {
        FSMBehaviour fsm = new FSMBehaviour();
        fsm.registerFirstState(new OneShotBehaviour() {
            @Override
            public void action() {
            }
        }, "A");
        assertThrows(IllegalArgumentException.class, () -> fsm.registerTransition("A", "Z", 0));
    }

    @Test
    void behavioursOfOneAgentTakeTurnsOneStepAtATime() {
        start("a", ag -> {
            ag.addBehaviour(counting("p", 3));
            ag.addBehaviour(counting("q", 3));
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("p0", "q0", "p1", "q1", "p2", "q2"), log);
    }

    @Test
    void aBehaviourThatThrowsIsRemovedAndTheAgentGoesOn() {
        start("a", ag -> {
            ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    throw new IllegalStateException("bug in user code");
                }
            });
            ag.addBehaviour(counting("ok", 2));
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("ok0", "ok1"), log);
    }

    @Test
    void doDeleteRunsTakeDownAndReleasesTheNameAndPort() {
        LambdaAgent agent = new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
            @Override
            public void action() {
                myAgent.doDelete();
            }
        }));
        AID a = rt.startAgentOnPort("a", agent, 7001);
        sim.runUntilQuiet(1_000);
        assertTrue(agent.tookDown);
        assertEquals(Agent.State.DELETED, agent.getState());
        assertFalse(rt.agents().contains(a));
        assertFalse(sim.network().isBound("h1", 7001));
        rt.startAgentOnPort("a", new LambdaAgent(ag -> { }), 7001);
    }

    @Test
    void aRemovedBehaviourIsNotRunAgain() {
        Behaviour[] holder = new Behaviour[1];
        start("a", ag -> {
            holder[0] = counting("r", 100);
            ag.addBehaviour(holder[0]);
            ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    myAgent.removeBehaviour(holder[0]);
                }
            });
        });
        sim.runUntilQuiet(1_000);
        assertEquals(List.of("r0"), log);
    }

    @Test
    void receiveWithATemplateTakesOnlyWhatMatches() {
        List<AclMessage> got = new ArrayList<>();
        Agent[] ref = new Agent[1];
        AID a = start("a", ag -> ref[0] = ag);
        tell(a, "x");
        tell(a, "y");
        sim.runUntilQuiet(1_000);
        AclMessage y = ref[0].receive(MessageTemplate.matchContent("y"));
        assertNotNull(y);
        assertEquals("y", y.getContent());
        assertNull(ref[0].receive(MessageTemplate.matchContent("y")));
        got.add(ref[0].receive());
        assertEquals("x", got.get(0).getContent());
        assertEquals(0, ref[0].getCurQueueSize());
    }

    @Test
    void blockingReceiveRefusesToBlockTheSharedLoop() {
        Agent[] ref = new Agent[1];
        start("a", ag -> ref[0] = ag);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> ref[0].blockingReceive());
        assertTrue(e.getMessage().contains("ThreadedBehaviourFactory"));
    }

    @Test
    void aFullMailboxDropsAndCountsNewMessages() {
        try (Simulation small = new Simulation(2, FaultPlan.NONE)) {
            AgentRuntime r = AgentRuntime.builder().clock(small.clock()).network(small.network()).host("h")
                    .mailboxCapacity(2).build();
            AID a = r.startAgent("a", new LambdaAgent(ag -> { }));
            r.startAgent("b", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    for (int i = 0; i < 5; i++) {
                        myAgent.send(new AclMessage(Performative.INFORM).addReceiver(a));
                    }
                }
            })));
            for (int i = 0; i < 100; i++) {
                r.doWork();
                small.clock().advanceMs(1);
            }
            assertEquals(2, r.agent(a).getCurQueueSize());
            assertEquals(3L, r.drops(a).get("mailbox-full"));
            r.close();
        }
    }

    @Test
    void behavioursRemovedOutsideARoundLeaveNoTrace() {
        Agent[] ref = new Agent[1];
        start("a", ag -> ref[0] = ag);
        for (int i = 0; i < 1_000; i++) {
            Behaviour b = counting("w", 1_000_000);
            ref[0].addBehaviour(b);
            ref[0].removeBehaviour(b);
        }
        assertEquals(0, ref[0].behaviourCount(), "a thousand added and removed: none left");
        assertEquals(0, ref[0].behaviourSlots(), "not even a hole in the list");
    }
}
