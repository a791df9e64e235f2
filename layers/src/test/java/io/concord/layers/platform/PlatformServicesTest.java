package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.layers.PlatformServices;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** White and yellow pages, naming, leaving, and a full range, on the virtual network. */
class PlatformServicesTest {

    /** Keeps what it receives. */
    static final class Inbox extends Agent {
        final List<AclMessage> got = new ArrayList<>();

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                    } else {
                        got.add(m);
                    }
                }
            });
        }
    }

    private static PlatformWorld world(Profile p) {
        PlatformWorld w = new PlatformWorld(5, FaultPlan.lossy(0.05, 0.05, 0.05, 0), p);
        return w;
    }

    private static <T> T await(PlatformWorld w, CompletableFuture<T> f) {
        assertTrue(w.sim.runUntil(f::isDone, 5_000), "no answer");
        return f.join();
    }

    @Test
    void agentsAddressEachOtherByNameOnly() {
        try (PlatformWorld w = world(Profile.CLASS_7)) {
            Inbox b = new Inbox();
            w.start("a");
            w.everStarted.add("b@sim");
            w.live.put("b", w.platform.startAgent("b", b));
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            Agent a = w.rt.agent(w.live.get("a"));
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(AID.local("b", "sim")); // no address: the LAL resolves it
            m.setContent("hello by name");
            a.send(m);
            assertTrue(w.sim.runUntil(() -> !b.got.isEmpty(), 2_000));
            assertEquals("hello by name", b.got.get(0).getContent());
            assertEquals("a@sim", b.got.get(0).getSender().name());
        }
    }

    @Test
    void yellowPagesThroughTheJavaApiSurviveTheContainersDeath() {
        try (PlatformWorld w = world(Profile.CLOSED)) {
            for (int i = 0; i < 5; i++) {
                w.start("s" + i);
            }
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            String container = w.containers().get(0);
            String seller = w.live.keySet().stream().filter(n -> !n.equals(container)).findFirst().orElseThrow();
            PlatformServices ps = Platform.of(w.rt.agent(w.live.get(seller)));
            await(w, ps.register(ServiceDescription.of("book-selling", "cheap-books").withProperty("price", "42")));
            w.sim.runUntil(w::converged, 2_000);
            // Every agent finds it in its own copy, without a message.
            for (String n : w.live.keySet()) {
                List<AgentEntry> found = Platform.of(w.rt.agent(w.live.get(n))).searchCopy(ServiceDescription.ofType("book-selling"));
                assertEquals(List.of(seller + "@sim"), found.stream().map(AgentEntry::name).toList(), n);
            }
            assertTrue(ps.searchCopy(ServiceDescription.ofType("book-buying")).isEmpty());
            assertTrue(ps.searchCopy(ServiceDescription.ofType("book-selling").withProperty("price", "41")).isEmpty());

            w.crash(container);
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            assertNotEquals(container, w.containers().get(0));
            String other = w.live.keySet().stream().filter(n -> !n.equals(seller)).findFirst().orElseThrow();
            PlatformServices asker = Platform.of(w.rt.agent(w.live.get(other)));
            List<AgentEntry> atDf = await(w, asker.searchAtDf(ServiceDescription.ofType("book-selling")));
            assertEquals(List.of(seller + "@sim"), atDf.stream().map(AgentEntry::name).toList());
            assertEquals("42", atDf.get(0).services().get(0).properties().get("price"));

            await(w, ps.deregister());
            w.sim.runUntil(w::converged, 2_000);
            assertTrue(asker.searchCopy(ServiceDescription.ofType("book-selling")).isEmpty());
        }
    }

    /** What JADE code does in setup(): search right after others registered, and deregister in takeDown(). */
    static final class SetupSearcher extends io.concord.core.agent.Agent {
        final CompletableFuture<List<AgentEntry>> atSetup = new CompletableFuture<>();
        List<AgentEntry> copyAtSetup;
        final CompletableFuture<List<AgentEntry>> atTakeDown = new CompletableFuture<>();
        List<AgentEntry> copyAtTakeDown;

        @Override
        protected void setup() {
            PlatformServices pages = Platform.of(this);
            copyAtSetup = pages.searchCopy(ServiceDescription.ofType("book-selling"));
            pages.register(ServiceDescription.ofType("book-buying"));
            pages.search(ServiceDescription.ofType("book-selling")).whenComplete((r, e) -> {
                if (e != null) {
                    atSetup.completeExceptionally(e);
                } else {
                    atSetup.complete(r);
                }
            });
        }

        @Override
        protected void takeDown() {
            PlatformServices pages = Platform.of(this);
            pages.deregister();
            copyAtTakeDown = pages.searchCopy(ServiceDescription.ofType("book-selling"));
            pages.search(ServiceDescription.ofType("book-selling")).whenComplete((r, e) -> {
                if (e != null) {
                    atTakeDown.completeExceptionally(e);
                } else {
                    atTakeDown.complete(r);
                }
            });
        }
    }

    @Test
    void searchFromSetupSeesWhatTheDfTookBeforeEvenBeforeTheListReachesTheAgent() {
        try (PlatformWorld w = world(Profile.CLASS_7)) {
            for (int i = 0; i < 4; i++) {
                w.start("s" + i);
            }
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            PlatformServices seller = Platform.of(w.rt.agent(w.live.get("s3")));
            await(w, seller.register(ServiceDescription.of("book-selling", "Dune")));
            SetupSearcher searcher = new SetupSearcher();
            w.everStarted.add("buyer@sim");
            io.concord.core.acl.AID buyer = w.platform.startAgent("buyer", searcher);
            w.live.put("buyer", buyer);
            List<AgentEntry> found = await(w, searcher.atSetup);
            assertEquals(List.of("s3@sim"), found.stream().map(AgentEntry::name).toList(),
                    "search answers once the container has: the registration the DF took is in it");
            assertEquals(List.of(), searcher.copyAtSetup, "(the agent's own copy, read in setup, had nothing yet)");
            assertTrue(w.sim.runUntil(() -> Platform.of(w.rt.agent(w.live.get("s3"))).searchCopy(ServiceDescription.ofType("book-buying"))
                    .stream().anyMatch(e -> e.name().equals("buyer@sim")), 2_000), "the buyer registered from setup()");
            w.stop("buyer");
            assertTrue(w.sim.runUntil(searcher.atTakeDown::isDone, 5_000), "a search from takeDown() does not hang");
            assertEquals(List.of("s3@sim"), searcher.copyAtTakeDown.stream().map(AgentEntry::name).toList(),
                    "the copy is read in takeDown()");
            java.util.concurrent.CompletionException late = org.junit.jupiter.api.Assertions.assertThrows(
                    java.util.concurrent.CompletionException.class, searcher.atTakeDown::join);
            assertTrue(late.getCause().getMessage().contains("the agent stopped before the DF answered"), late.getMessage());
            assertTrue(w.sim.runUntil(() -> Platform.of(w.rt.agent(w.live.get("s3"))).searchCopy(ServiceDescription.ofType("book-buying"))
                    .isEmpty(), 2_000), "deregistered from takeDown()");
        }
    }

    @Test
    void amsAndDfAnswerAclRequestsByName() {
        try (PlatformWorld w = world(Profile.CLASS_3)) {
            Inbox asker = new Inbox();
            w.start("x");
            w.start("y");
            w.everStarted.add("asker@sim");
            w.live.put("asker", w.platform.startAgent("asker", asker));
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            Agent a = w.rt.agent(w.live.get("asker"));

            AclMessage reg = new AclMessage(Performative.REQUEST);
            reg.addReceiver(AID.local("df", "sim"));
            reg.setContent("register services=t=weather;n=forecast");
            reg.setReplyWith("r1");
            a.send(reg);
            assertTrue(w.sim.runUntil(() -> asker.got.size() == 1, 2_000));
            assertEquals(Performative.INFORM, asker.got.get(0).getPerformative());
            assertEquals("r1", asker.got.get(0).getInReplyTo());

            AclMessage q = new AclMessage(Performative.QUERY_REF);
            q.addReceiver(AID.local("ams", "sim"));
            q.setContent("agents");
            a.send(q);
            AclMessage s = new AclMessage(Performative.REQUEST);
            s.addReceiver(AID.local("df", "sim"));
            s.setContent("search template=t=weather");
            a.send(s);
            AclMessage bad = new AclMessage(Performative.REQUEST);
            bad.addReceiver(AID.local("df", "sim"));
            bad.setContent("fly-to the=moon");
            a.send(bad);
            assertTrue(w.sim.runUntil(() -> asker.got.size() == 4, 2_000));
            String agents = asker.got.get(1).getContent();
            assertTrue(agents.startsWith("result count=3"), agents);
            assertTrue(agents.contains("\nx@sim ") && agents.contains("\ny@sim ") && agents.contains("\nasker@sim "), agents);
            String found = asker.got.get(2).getContent();
            assertTrue(found.startsWith("result count=1\nasker@sim "), found);
            assertEquals(Performative.NOT_UNDERSTOOD, asker.got.get(3).getPerformative());
            assertTrue(asker.got.get(3).getContent().contains("fly-to"));
        }
    }

    @Test
    void aSubscriberIsToldOfEachRegistrationAndDeregistrationThatMatchesUntilItCancels() {
        try (PlatformWorld w = world(Profile.CLASS_3)) {
            Inbox watcher = new Inbox();
            w.start("early");
            w.start("late");
            w.everStarted.add("watcher@sim");
            w.live.put("watcher", w.platform.startAgent("watcher", watcher));
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            PlatformServices early = Platform.of(w.rt.agent(w.live.get("early")));
            PlatformServices late = Platform.of(w.rt.agent(w.live.get("late")));
            await(w, early.register(ServiceDescription.of("weather", "forecast")));
            Agent a = w.rt.agent(w.live.get("watcher"));

            AclMessage sub = new AclMessage(Performative.SUBSCRIBE);
            sub.addReceiver(AID.local("df", "sim"));
            sub.setContent("subscribe template=t=weather");
            sub.setConversationId("c1");
            a.send(sub);
            assertTrue(w.sim.runUntil(() -> watcher.got.size() == 1, 2_000), "told at once of what matches already");
            assertTrue(watcher.got.get(0).getContent().startsWith("result count=1\nearly@sim "), watcher.got.get(0).getContent());
            assertEquals("c1", watcher.got.get(0).getConversationId());

            await(w, late.register(ServiceDescription.of("weather", "radar")));
            assertTrue(w.sim.runUntil(() -> watcher.got.size() == 2, 2_000), "told of a registration made later");
            String registered = watcher.got.get(1).getContent();
            assertTrue(registered.startsWith("result count=1\nlate@sim ") && registered.contains("radar"), registered);

            await(w, Platform.of(a).register(ServiceDescription.of("news", "daily")));
            w.sim.runUntil(w::converged, 2_000);
            assertEquals(2, watcher.got.size(), "a registration that does not match is not told");

            await(w, late.deregister());
            assertTrue(w.sim.runUntil(() -> watcher.got.size() == 3, 2_000), "told of a deregistration");
            String gone = watcher.got.get(2).getContent();
            assertTrue(gone.startsWith("result count=1\nlate@sim ") && !gone.contains("radar"), gone);
            assertEquals(Performative.INFORM, watcher.got.get(2).getPerformative());

            AclMessage cancel = new AclMessage(Performative.CANCEL);
            cancel.addReceiver(AID.local("df", "sim"));
            cancel.setConversationId("c1");
            a.send(cancel);
            w.sim.runUntil(w::converged, 2_000);
            await(w, late.register(ServiceDescription.of("weather", "radar")));
            w.sim.runUntil(w::converged, 2_000);
            assertEquals(3, watcher.got.size(), "nothing after the cancel");
        }
    }

    @Test
    void aSubscriberIsToldWhenARegisteredAgentLeavesThePlatform() {
        try (PlatformWorld w = world(Profile.CLASS_3)) {
            Inbox watcher = new Inbox();
            w.start("a1");
            w.start("seller");
            w.everStarted.add("watcher@sim");
            w.live.put("watcher", w.platform.startAgent("watcher", watcher));
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            String container = w.containers().get(0);
            String seller = container.equals("seller") ? "a1" : "seller";
            await(w, Platform.of(w.rt.agent(w.live.get(seller))).register(ServiceDescription.ofType("weather")));
            AclMessage sub = new AclMessage(Performative.SUBSCRIBE);
            sub.addReceiver(AID.local("df", "sim"));
            sub.setContent("subscribe template=t=weather");
            sub.setConversationId("c2");
            w.rt.agent(w.live.get("watcher")).send(sub);
            assertTrue(w.sim.runUntil(() -> watcher.got.size() == 1, 2_000), "told at once of the registered agent");

            w.stop(seller);
            assertTrue(w.sim.runUntil(() -> watcher.got.size() == 2, 5_000), "told when it left");
            String gone = watcher.got.get(1).getContent();
            assertTrue(gone.startsWith("result count=1\n" + seller + "@sim ") && !gone.contains("weather"), gone);
        }
    }

    @Test
    void anUnknownNameGetsTheFipaFailure() {
        try (PlatformWorld w = world(Profile.CLOSED)) {
            Inbox a = new Inbox();
            w.everStarted.add("a@sim");
            w.live.put("a", w.platform.startAgent("a", a));
            w.sim.runUntil(w::converged, 2_000);
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("nobody", "sim"));
            w.rt.agent(w.live.get("a")).send(m);
            assertTrue(w.sim.runUntil(() -> !a.got.isEmpty(), 1_000));
            assertEquals(Performative.FAILURE, a.got.get(0).getPerformative());
            assertTrue(a.got.get(0).getContent().contains("Agent not found: nobody@sim"));
        }
    }

    @Test
    void anAgentThatLeavesIsRemovedAtOnceNotAfterItsTimeout() {
        try (PlatformWorld w = world(Profile.CLOSED)) {
            for (int i = 0; i < 4; i++) {
                w.start("m" + i);
            }
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            String container = w.containers().get(0);
            String leaver = w.live.keySet().stream().filter(n -> !n.equals(container)).findFirst().orElseThrow();
            long timeout = PlatformConfig.defaults().timeoutMs(4);
            w.stop(leaver);
            // Well before the silence timeout could have removed it.
            assertTrue(w.sim.runUntil(w::converged, timeout / 3), w.describe());
            // The container leaves too: the others elect at once.
            w.stop(container);
            assertTrue(w.sim.runUntil(w::converged, timeout / 3), w.describe());
            assertFalse(w.containers().contains(container));
        }
    }

    @Test
    void aFullPortRangeIsAClearError() {
        try (Simulation sim = new Simulation(1, FaultPlan.NONE)) {
            var rt = sim.newRuntime("h1");
            Platform p = Platform.builder().runtime(rt).ports(new PortRange(7001, 3, 10))
                    .safetyStack(SafetyStack.builder().profile(Profile.CLOSED).build()).build();
            for (int i = 0; i < 3; i++) {
                p.startAgent("a" + i, new PlatformWorld.Idle());
            }
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> p.startAgent("a3", new PlatformWorld.Idle()));
            assertTrue(e.getMessage().contains("port range 7001-7003 on h1 is full"), e.getMessage());
            assertTrue(e.getMessage().contains("-ports 7001-7006"), e.getMessage());
        }
    }

    @Test
    void aNewcomerWhoseContainerDiedAsksAKnownAgentForTheLastListAndJoinsTheNextContainer() {
        try (PlatformWorld w = new PlatformWorld(9, FaultPlan.NONE, Profile.CLOSED)) {
            for (int i = 0; i < 4; i++) {
                w.start("m" + i);
            }
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            List<String> newcomerEvents = new ArrayList<>();
            w.sim.trace().addListener((ns, node, event, detail) -> {
                if (node.equals("late@sim") && event.startsWith("platform-")) {
                    newcomerEvents.add(event);
                }
            });
            String container = w.containers().get(0);
            // The members still name the old container when the newcomer asks: its joins go nowhere.
            w.crash(container);
            w.start("late");
            assertTrue(w.sim.runUntil(w::converged, 10_000), w.describe());
            assertTrue(newcomerEvents.contains("platform-join-failed"), newcomerEvents.toString());
            assertTrue(newcomerEvents.contains("platform-join-from-copy"), newcomerEvents.toString());
            assertFalse(w.containers().contains("late"), "the newcomer took over instead of joining: " + w.describe());
        }
    }

    @Test
    void malformedPlatformMessagesAreDroppedAndCountedAndChangeNothing() {
        try (PlatformWorld w = world(Profile.CLOSED)) {
            for (int i = 0; i < 3; i++) {
                w.start("g" + i);
            }
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            String container = w.containers().get(0);
            Agent sender = w.rt.agent(w.live.get(w.live.keySet().stream().filter(n -> !n.equals(container)).findFirst().orElseThrow()));
            java.util.SplittableRandom r = new java.util.SplittableRandom(4);
            String[] commands = {"lal", "alive", "join", "joined", "container", "seeking", "who-is-container", "leave",
                    "agent-info", "lal-held", "lal-copy", "lal-request", "nonsense", ""};
            for (int i = 0; i < 2_000; i++) {
                StringBuilder b = new StringBuilder(commands[r.nextInt(commands.length)]);
                int params = r.nextInt(4);
                for (int k = 0; k < params; k++) {
                    b.append(' ').append(new String[]{"term", "seq", "page", "pages", "period", "timeout"}[r.nextInt(6)])
                            .append('=').append(r.nextInt(3) == 0 ? "x" : Long.toString(r.nextLong(-5, 1L << 40)));
                }
                if (r.nextBoolean()) {
                    b.append('\n').append(r.nextBoolean() ? "z@sim udp://h1:1 5 -" : "garbage line");
                }
                AclMessage m = new AclMessage(r.nextBoolean() ? Performative.INFORM : Performative.REQUEST);
                m.addReceiver(AID.local(r.nextBoolean() ? container : "g" + r.nextInt(3), "sim"));
                m.setOntology("concord-platform");
                m.setContent(b.toString());
                sender.send(m);
                w.sim.runFor(1);
            }
            w.sim.runFor(2_000);
            assertTrue(w.rt.drops().getOrDefault("malformed-platform", 0L) > 0, w.rt.drops().toString());
            assertEquals(0L, w.rt.drops().getOrDefault("layer-error", 0L), w.rt.drops().toString());
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            assertEquals(3, w.live.size());
        }
    }
}
