package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.layer.Envelope;
import io.concord.core.acl.Performative;
import io.concord.layers.platform.Role;
import io.concord.layers.platform.PlatformMessage.AgentInfo;
import io.concord.layers.platform.PlatformMessage.AgentInfoRequest;
import io.concord.layers.platform.PlatformMessage.Alive;
import io.concord.layers.platform.PlatformMessage.ContainerIs;
import io.concord.layers.platform.PlatformMessage.Held;
import io.concord.layers.platform.PlatformMessage.Join;
import io.concord.layers.platform.PlatformMessage.Joined;
import io.concord.layers.platform.PlatformMessage.LalPage;
import io.concord.layers.platform.PlatformMessage.LalRequest;
import io.concord.layers.platform.PlatformMessage.Leave;
import io.concord.layers.platform.PlatformMessage.Page;
import io.concord.layers.platform.PlatformMessage.Seeking;
import io.concord.layers.platform.PlatformMessage.WhoIsContainer;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static io.concord.layers.platform.Protocol.P_DISCOVERY;
import static io.concord.layers.platform.Protocol.P_LAL;
import static io.concord.layers.platform.Protocol.P_MAINTENANCE;
import static io.concord.layers.platform.OneAgent.other;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The container layer's rules, one test each, named after the rule (dissertation figs. 5.6 to
 * 5.12): one agent's layer alone on the layer harness with a manual clock; the test plays the
 * other agents (and the other hosts' containers). The whole platform in simulation is
 * {@link PlatformSimulationTest}'s, several hosts in simulation {@link NetworkSimulationTest}'s.
 */
class ContainerRulesTest {

    private static List<String> names(List<AgentEntry> entries) {
        List<String> out = new ArrayList<>();
        for (AgentEntry e : entries) {
            out.add(e.name());
        }
        return out;
    }

    /** An agent made member of {@code container} (term 1) with the list given, by a joined and a LAL. */
    private static OneAgent memberOf(AgentEntry container, List<AgentEntry> others) {
        return memberOf(container, others, false);
    }

    /** ... the container running in this agent's runtime or not. */
    private static OneAgent memberOf(AgentEntry container, List<AgentEntry> others, boolean sameRuntime) {
        OneAgent a = new OneAgent("me", 7001, container.port());
        if (sameRuntime) {
            a.coLocated.add(container.transportAddress());
        }
        a.from(container, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, container, null));
        a.from(container, Performative.CONFIRM, P_LAL, new Joined(1, 40, 250, container));
        List<AgentEntry> all = new ArrayList<>(others);
        all.add(container);
        all.add(a.self);
        a.from(container, Performative.INFORM_REF, P_LAL, new LalPage(1, 2, 40, 250, Page.of(0, 1, body(all))));
        assertEquals(Role.MEMBER, a.role());
        a.sent();
        return a;
    }

    private static String body(List<AgentEntry> entries) {
        return String.join("\n", AgentLists.pages(entries, 100_000));
    }

    /** An agent that is container (alone in its range), with these members joined. */
    private static OneAgent containerWith(AgentEntry... members) {
        OneAgent c = new OneAgent("me", 7001);
        for (AgentEntry m : members) {
            c.from(m, Performative.INFORM_REF, P_LAL, new Join(1, m));
        }
        c.advance(10); // the list goes out
        c.sent();
        return c;
    }

    @Nested
    class Seeking_ {

        @Test
        void anAgentAloneInItsPortRangeIsContainerAtOnce() {
            OneAgent a = new OneAgent("a", 7001);
            assertEquals(Role.CONTAINER, a.role());
            assertEquals(1, a.layer.term());
            assertEquals(List.of("a@p"), names(List.copyOf(a.layer.agents())));
        }

        @Test
        void aNewcomerAsksTheNearestHeldPortsFirstABatchAtATime() {
            int[] ports = new int[40];
            for (int i = 0; i < ports.length; i++) {
                ports[i] = 7100 - i * 2; // 7100, 7098, ... 7022: the nearest to 7001 last
            }
            OneAgent a = new OneAgent("a", 7001, ports);
            List<OneAgent.Out> asked = a.sent();
            assertEquals(16, asked.size(), "the first batch");
            for (OneAgent.Out o : asked) {
                assertEquals(Performative.QUERY_REF, o.act());
                assertTrue(o.what() instanceof WhoIsContainer, o.toString());
                assertTrue(o.at().port() <= 7052, "nearest first: " + o.at());
                assertTrue(o.to().startsWith("*@"), "to whoever holds the port: " + o.to());
            }
            assertEquals(Role.SEEKING, a.role());
        }

        @Test
        void aNewcomerJoinsTheContainerItIsToldOfAndIsMemberWhenItConfirms() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = new OneAgent("a", 7001, 7002);
            a.sent();
            a.from(c, Performative.INFORM, P_DISCOVERY, new ContainerIs(3, c, null));
            List<Join> joins = a.sent(Join.class);
            assertEquals(1, joins.size());
            assertEquals(3, joins.get(0).term());
            assertEquals(Role.SEEKING, a.role(), "a member only once confirmed");
            a.from(c, Performative.CONFIRM, P_LAL, new Joined(3, 40, 250, c));
            assertEquals(Role.MEMBER, a.role());
            assertEquals("c@p", a.layer.containerName());
            assertEquals(3, a.layer.term());
        }

        @Test
        void whenEveryoneAskedIsSeekingTheEldestBecomesContainer() {
            OneAgent a = new OneAgent("a", 7001, 7002);
            a.sent();
            a.from(other("b", 7002, -500), Performative.INFORM, P_DISCOVERY, new Seeking(0, 0, other("b", 7002, -500)));
            assertEquals(Role.CONTAINER, a.role(), "a is older than b");
            assertEquals(1, a.layer.term());
            // ... and tells the other seeker.
            List<ContainerIs> told = a.sent(ContainerIs.class);
            assertEquals(1, told.size());
            assertEquals("a@p", told.get(0).container().name());
        }

        @Test
        void aYoungerSeekerExcludesItselfAndAsksAgainAfterTheElectionTimeout() {
            OneAgent a = new OneAgent("a", 7001, 7002);
            a.sent();
            a.from(other("b", 7002, 500), Performative.INFORM, P_DISCOVERY, new Seeking(0, 0, other("b", 7002, 500)));
            assertEquals(Role.SEEKING, a.role(), "b is older: a waits for it");
            a.advance(59);
            assertTrue(a.sent(WhoIsContainer.class).isEmpty(), "nothing before the election timeout");
            a.advance(1);
            List<WhoIsContainer> again = a.sent(WhoIsContainer.class);
            assertEquals(1, again.size(), "the next round asks again");
            assertEquals(1, again.get(0).round());
        }

        @Test
        void theBetterOfTwoClaimsIsJoined() {
            OneAgent a = new OneAgent("a", 7001, 7002, 7003);
            a.sent();
            AgentEntry c1 = other("c1", 7002, 1_000);
            AgentEntry c2 = other("c2", 7003, 100);
            a.from(c1, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c1, null));
            assertEquals(List.of("c1@p"), a.sent().stream().filter(o -> o.what() instanceof Join).map(OneAgent.Out::to).toList());
            // c2 is younger, but of a later term: the later term wins.
            a.from(c2, Performative.INFORM, P_DISCOVERY, new ContainerIs(2, c2, null));
            assertEquals(List.of("c2@p"), a.sent().stream().filter(o -> o.what() instanceof Join).map(OneAgent.Out::to).toList());
            a.from(c1, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c1, null));
            assertTrue(a.sent(Join.class).isEmpty(), "the earlier term does not take it back");
        }

        @Test
        void aNewcomerWhoseJoinsFailAsksAKnownAgentForTheLastList() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = new OneAgent("a", 7001, 7002, 7003);
            a.sent();
            AgentEntry b = other("b", 7003, 2_000);
            a.from(b, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c, b));
            assertEquals(1, a.sent(Join.class).size());
            // Joins at 0, 60, 180, 420 ms; the fourth is given up at 900 ms.
            a.advance(899);
            assertEquals(3, a.sent(Join.class).size());
            assertTrue(a.sent(LalRequest.class).isEmpty());
            a.advance(1);
            List<OneAgent.Out> out = a.sent();
            assertEquals(1, out.size(), out.toString());
            assertTrue(out.get(0).what() instanceof LalRequest, out.toString());
            assertTrue(!out.get(0).to().equals("c@p"), "not the container that failed: " + out);
            assertEquals(Role.MEMBER, a.role());
            assertNull(a.layer.containerName(), "no container until the copy or an election");
        }
    }

    @Nested
    class Member {

        @Test
        void aMemberAppliesTheListOnlyOnceEveryPageIsInAndConfirmsIt() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = new OneAgent("me", 7001, 7002);
            a.from(c, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c, null));
            a.from(c, Performative.CONFIRM, P_LAL, new Joined(1, 40, 250, c));
            a.sent();
            List<AgentEntry> all = new ArrayList<>(List.of(c, a.self));
            for (int i = 0; i < 30; i++) {
                all.add(other("x" + i, 7100 + i, -i));
            }
            List<String> pages = AgentLists.pages(all, 512);
            assertTrue(pages.size() > 2, "the list takes several pages");
            for (int i = pages.size() - 1; i > 0; i--) {
                a.from(c, Performative.INFORM_REF, P_LAL, new LalPage(1, 5, 40, 250, Page.of(i, pages.size(), pages.get(i))));
            }
            assertEquals(List.of("c@p"), names(List.copyOf(a.layer.agents())), "only the container it joined, before the last page");
            assertTrue(a.sent(Held.class).isEmpty());
            a.from(c, Performative.INFORM_REF, P_LAL, new LalPage(1, 5, 40, 250, Page.of(0, pages.size(), pages.get(0))));
            assertEquals(32, a.layer.agents().size());
            assertEquals(5, a.layer.lalSequence());
            List<Held> held = a.sent(Held.class);
            assertEquals(1, held.size());
            assertEquals(5, held.get(0).seq());
        }

        @Test
        void aMemberConfirmsEachAliveWithTheVersionsItHolds() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            a.from(c, Performative.INFORM, P_MAINTENANCE, new Alive(1, 2, 40, 250, c));
            List<OneAgent.Out> out = a.sent();
            assertEquals(1, out.size());
            assertEquals(Performative.CONFIRM, out.get(0).act());
            Held h = (Held) out.get(0).what();
            assertTrue(h.alive());
            assertEquals(2, h.seq());
        }

        @Test
        void aMemberThatHearsNothingForTheTimeoutAndIsTheEldestLeftBecomesContainerOfTheNextTerm() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of(other("y", 7003, -1_000)));
            a.advance(249);
            assertEquals(Role.MEMBER, a.role());
            a.advance(1);
            assertEquals(Role.CONTAINER, a.role());
            assertEquals(2, a.layer.term());
            assertTrue(a.layer.agents().stream().noneMatch(e -> e.name().equals("c@p")), "the dead container is not listed");
            // It asks every listed agent for its information (fig. 5.11).
            List<OneAgent.Out> asks = a.sent();
            assertEquals(List.of("y@p"), asks.stream().filter(o -> o.what() instanceof AgentInfoRequest).map(OneAgent.Out::to).toList());
        }

        @Test
        void aMemberThatIsNotTheEldestWaitsForTheSuccessorAndSuspectsItInTurn() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, 500);
            OneAgent a = memberOf(c, List.of(y));
            a.advance(250);
            assertEquals(Role.MEMBER, a.role(), "y is older: a waits for it");
            assertNull(a.layer.containerName());
            a.advance(249);
            assertEquals(Role.MEMBER, a.role());
            a.advance(1);
            assertEquals(Role.CONTAINER, a.role(), "y stayed silent too");
        }

        /**
         * A container in this agent's runtime is seen leaving it at once; its alives come rarer while
         * nothing changes, up to {@link ContainerRole#LOCAL_CYCLE_MAX_MS}: its silence is allowed that
         * (and up to the next whole second, when the watches of a runtime's members end together).
         */
        @Test
        void aMemberOfAContainerInItsRuntimeAllowsItsSilenceTheLongestQuietCycle() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of(), true);
            long allowed = (250 + ContainerRole.LOCAL_CYCLE_MAX_MS + 999) / 1_000 * 1_000;
            a.advance(allowed - 1);
            assertEquals(Role.MEMBER, a.role());
            assertEquals("c@p", a.layer.containerName());
            a.advance(1);
            assertEquals(Role.CONTAINER, a.role(), "silent for longer: failover, as for any container");
        }

        /**
         * Where the runtime lets it read its container's layer in memory, a member needs no word from
         * it: at the end of each watch it looks. Container still, of the same term: nothing happens and
         * nothing is sent; with a newer list, the member says which version it holds (and is sent what
         * it misses); no longer container, failover.
         */
        @Test
        void aMemberReadsAContainerOfItsRuntimeInMemoryInsteadOfWaitingForItsWord() {
            OneAgent cont = new OneAgent("c", 7002);
            assertEquals(Role.CONTAINER, cont.role());
            AgentEntry c = cont.self;
            OneAgent a = new OneAgent("me", 7001, c.port());
            a.coLocated.add(c.transportAddress());
            a.peers.put(c.transportAddress(), cont.layer);
            a.from(c, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c, null));
            a.from(c, Performative.CONFIRM, P_LAL, new Joined(1, 40, 250, c));
            a.from(c, Performative.INFORM_REF, P_LAL, new LalPage(1, cont.layer.lalSequence(), 40, 250,
                    Page.of(0, 1, body(List.of(c, a.self)))));
            assertEquals(Role.MEMBER, a.role());
            a.sent();
            a.advance(10 * 60_000);
            assertEquals(Role.MEMBER, a.role());
            assertEquals("c@p", a.layer.containerName());
            assertTrue(a.sent().isEmpty(), "ten minutes, not a word either way");
            // The container's list moves on, and the change does not reach this member.
            AgentEntry y = other("y", 7003, -10);
            cont.from(y, Performative.INFORM_REF, P_LAL, new Join(1, y));
            a.advance(ContainerRole.LOCAL_CYCLE_MAX_MS + 1_250);
            List<Held> held = a.sent(Held.class);
            assertEquals(1, held.size(), "it says which version it holds");
            assertTrue(held.get(0).seq() < cont.layer.lalSequence());
            // The container stops being one without a word (it yields to an older claim).
            AgentEntry older = other("o", 7009, 60_000);
            cont.from(older, Performative.INFORM, P_MAINTENANCE, new Alive(1, 1, 40, 250, older));
            assertEquals(Role.MEMBER, cont.role());
            a.advance(ContainerRole.LOCAL_CYCLE_MAX_MS + 1_250);
            assertTrue(a.role() != Role.MEMBER || !"c@p".equals(a.layer.containerName()), "failover: " + a.role());
        }

        @Test
        void anAliveKeepsTheMemberFromFailover() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            for (int i = 0; i < 10; i++) {
                a.advance(200);
                a.from(c, Performative.INFORM, P_MAINTENANCE, new Alive(1, 2, 40, 250, c));
            }
            assertEquals(Role.MEMBER, a.role());
            assertEquals("c@p", a.layer.containerName());
        }

        @Test
        void aMemberJoinsABetterContainerAndTellsAWorseOneOfItsOwn() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            AgentEntry worse = other("w", 7004, 10);
            a.from(worse, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, worse, null));
            List<OneAgent.Out> out = a.sent();
            assertEquals(1, out.size());
            assertEquals("w@p", out.get(0).to());
            assertEquals("c@p", ((ContainerIs) out.get(0).what()).container().name());
            AgentEntry better = other("b", 7005, 10);
            a.from(better, Performative.INFORM, P_DISCOVERY, new ContainerIs(2, better, null));
            List<Join> joins = a.sent(Join.class);
            assertEquals(1, joins.size());
            assertEquals(2, joins.get(0).term());
        }

        @Test
        void whenTheContainerLeavesTheMembersFailOverAtOnce() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            a.from(c, Performative.INFORM, P_MAINTENANCE, new Leave(1));
            assertEquals(Role.CONTAINER, a.role());
            assertEquals(2, a.layer.term());
        }

        @Test
        void onlyTheAgentItselfSaysItLeaves() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, -1_000);
            OneAgent a = memberOf(c, List.of(y));
            a.from(y, Performative.INFORM, P_MAINTENANCE, new Leave(1));
            assertEquals(Role.MEMBER, a.role(), "a member's leave is its container's business");
            assertEquals("c@p", a.layer.containerName());
        }
    }

    @Nested
    class Container {

        @Test
        void theContainerRegistersAJoinConfirmsItAndDistributesTheList() {
            OneAgent c = new OneAgent("me", 7001);
            AgentEntry m = other("m", 7002, -10);
            c.from(m, Performative.INFORM_REF, P_LAL, new Join(1, m));
            List<OneAgent.Out> out = c.sent();
            assertEquals(1, out.size());
            Joined j = (Joined) out.get(0).what();
            assertEquals(Performative.CONFIRM, out.get(0).act());
            assertEquals(1, j.term());
            assertTrue(j.timeout() >= PlatformConfig.MIN_TIMEOUT_MS);
            c.advance(5); // the push delay gathers changes
            List<LalPage> lists = c.sent(LalPage.class);
            assertEquals(1, lists.size());
            assertEquals(List.of("m@p", "me@p"), names(lists.get(0).page().entries()));
        }

        @Test
        void theContainerTellsEveryMemberEachPeriodThatItIsAlive() {
            AgentEntry m1 = other("m1", 7002, -10);
            AgentEntry m2 = other("m2", 7003, -10);
            OneAgent c = containerWith(m1, m2);
            c.advance(41);
            List<OneAgent.Out> alive = c.sent().stream().filter(o -> o.what() instanceof Alive).toList();
            assertEquals(List.of("m1@p", "m2@p"), alive.stream().map(OneAgent.Out::to).toList());
        }

        /**
         * With every member in its runtime (watched for leaving it, nothing lost between them), an idle
         * container's cycle waits {@link ContainerRole#LOCAL_ALIVE_EVERY} periods, then twice as long
         * at each cycle that finds nothing changed, up to {@link ContainerRole#LOCAL_CYCLE_MAX_MS};
         * a change of the list starts again from the shortest wait.
         */
        @Test
        void anIdleContainerWithItsMembersInItsRuntimeWaitsTwiceAsLongEachQuietCycle() {
            AgentEntry m1 = other("m1", 7002, -10);
            AgentEntry m2 = other("m2", 7003, -10);
            OneAgent c = new OneAgent("me", 7001);
            c.coLocated.add(m1.transportAddress());
            c.coLocated.add(m2.transportAddress());
            c.from(m1, Performative.INFORM_REF, P_LAL, new Join(1, m1));
            c.from(m2, Performative.INFORM_REF, P_LAL, new Join(1, m2));
            long shortest = PlatformConfig.defaults().periodMs(3) * ContainerRole.LOCAL_ALIVE_EVERY;
            List<Long> gaps = alivesTo(c, "m1@p", 10 * 60_000);
            List<Long> expected = new ArrayList<>();
            for (long g = shortest; expected.size() < gaps.size(); g = Math.min(2 * g, ContainerRole.LOCAL_CYCLE_MAX_MS)) {
                expected.add(g);
            }
            assertEquals(expected, gaps);
            assertTrue(gaps.size() < 40, "ten idle minutes, " + gaps.size() + " alives: " + gaps);
            assertEquals(List.of("m1@p", "m2@p", "me@p"), names(List.copyOf(c.layer.agents())), "nobody was taken for dead");
            // A newcomer of the same runtime: the cycle after the change waits the shortest again.
            AgentEntry m3 = other("m3", 7004, -10);
            c.coLocated.add(m3.transportAddress());
            c.from(m3, Performative.INFORM_REF, P_LAL, new Join(1, m3));
            List<Long> after = alivesTo(c, "m1@p", 2 * ContainerRole.LOCAL_CYCLE_MAX_MS + 1);
            assertTrue(after.size() >= 1, after.toString());
            assertEquals(PlatformConfig.defaults().periodMs(4) * ContainerRole.LOCAL_ALIVE_EVERY, after.get(0), "after the change: " + after);
        }

        /** The gaps between the alives sent to {@code member} over {@code ms} (the first counted from the start). */
        private static List<Long> alivesTo(OneAgent c, String member, long ms) {
            List<Long> gaps = new ArrayList<>();
            long last = -1;
            for (long t = 1; t <= ms; t++) {
                c.advance(1);
                if (c.sent().stream().anyMatch(o -> o.what() instanceof Alive && o.to().equals(member))) {
                    if (last >= 0) {
                        gaps.add(t - last);
                    }
                    last = t;
                }
            }
            return gaps;
        }

        /** Members it reads in memory (ContainerRulesTest.Member) get no alive at all. */
        @Test
        void anIdleContainerSendsNoAliveToAMemberThatReadsItInMemory() {
            OneAgent member = new OneAgent("m1", 7002);
            AgentEntry m1 = member.self;
            OneAgent c = new OneAgent("me", 7001);
            c.coLocated.add(m1.transportAddress());
            c.peers.put(m1.transportAddress(), member.layer);
            c.from(m1, Performative.INFORM_REF, P_LAL, new Join(1, m1));
            assertTrue(alivesTo(c, "m1@p", 10 * 60_000).isEmpty());
            assertTrue(c.sent().stream().noneMatch(o -> o.what() instanceof Alive));
            assertEquals(List.of("m1@p", "me@p"), names(List.copyOf(c.layer.agents())));
        }

        @Test
        void aMemberSilentForTheTimeoutIsRemovedAndTheListDistributed() {
            AgentEntry m1 = other("m1", 7002, -10);
            AgentEntry m2 = other("m2", 7003, -10);
            OneAgent c = containerWith(m1, m2);
            long seq = c.layer.lalSequence();
            // m1 confirms every alive, m2 never does.
            for (int t = 0; t < 400; t += 20) {
                c.advance(20);
                c.from(m1, Performative.CONFIRM, P_MAINTENANCE, new Held(true, 1, c.layer.lalSequence(), 0L, "-"));
            }
            assertEquals(List.of("m1@p", "me@p"), names(List.copyOf(c.layer.agents())));
            assertTrue(c.layer.lalSequence() > seq);
            // As what changed: m1 holds the version last pushed, so it gets m2's removal, not the whole list.
            assertTrue(c.sent().stream().anyMatch(o -> o.what() instanceof PlatformMessage.LalDelta d && o.to().equals("m1@p")
                    && d.removed() == 1 && names(d.page().entries()).equals(List.of("m2@p"))), "the removal is distributed");
        }

        @Test
        void aContainerThatHearsAnOlderContainerOfTheSameTermYieldsAndJoinsIt() {
            AgentEntry m = other("m", 7002, -10);
            OneAgent c = containerWith(m);
            AgentEntry older = other("o", 7009, 60_000);
            c.from(older, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, older, null));
            assertEquals(Role.MEMBER, c.role());
            List<OneAgent.Out> out = c.sent();
            assertTrue(out.stream().anyMatch(o -> o.to().equals("m@p") && o.what() instanceof ContainerIs ci
                    && ci.container().name().equals("o@p")), "its member is told of the winner: " + out);
            assertTrue(out.stream().anyMatch(o -> o.to().equals("o@p") && o.what() instanceof Join), "it joins the winner: " + out);
            // Its own timers ended with the role: no alive any more.
            c.advance(500);
            assertTrue(c.sent(Alive.class).isEmpty());
        }

        @Test
        void aContainerThatHearsAWorseClaimTellsItOfItself() {
            OneAgent c = containerWith(other("m", 7002, -10));
            AgentEntry younger = other("y", 7009, -60_000);
            c.from(younger, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, younger, null));
            assertEquals(Role.CONTAINER, c.role());
            List<OneAgent.Out> out = c.sent();
            assertEquals(1, out.size());
            assertEquals("y@p", out.get(0).to());
            assertEquals("me@p", ((ContainerIs) out.get(0).what()).container().name());
        }

        @Test
        void aMemberThatLeavesIsRemovedAtOnce() {
            AgentEntry m = other("m", 7002, -10);
            OneAgent c = containerWith(m, other("n", 7003, -10));
            c.from(m, Performative.INFORM, P_MAINTENANCE, new Leave(1));
            assertEquals(List.of("me@p", "n@p"), names(List.copyOf(c.layer.agents())));
        }

        @Test
        void aNewContainerTakesTheAnswersToItsRequestForInformation() {
            AgentEntry c0 = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, -1_000);
            OneAgent a = memberOf(c0, List.of(y));
            a.advance(250);
            assertEquals(Role.CONTAINER, a.role());
            a.sent();
            AgentEntry yWithService = y.withServices(List.of(ServiceDescription.ofType("book-selling")));
            a.from(y, Performative.INFORM, P_LAL, new AgentInfo(2, List.of(yWithService)));
            assertEquals(List.of("y@p"), names(a.layer.search(ServiceDescription.ofType("book-selling"))));
        }
    }

    /** Who may say what: a claim counts only on the claimed container's own authenticated word. */
    @Nested
    class Claims {

        @Test
        void aClaimInAFrameForAnyAgentMakesAMemberOnlyAskTheClaimedContainer() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry x = other("x", 7009, 2_000);
            OneAgent a = memberOf(c, List.of(x));
            a.fromAny(x, Performative.INFORM, P_DISCOVERY, new ContainerIs(99, x, x));
            List<OneAgent.Out> out = a.sent();
            assertEquals(Role.MEMBER, a.role());
            assertEquals("c@p", a.layer.containerName(), "a key holder's claim changes nothing by itself");
            assertTrue(out.stream().noneMatch(o -> o.what() instanceof Join), "no join on a forged claim: " + out);
            assertEquals(List.of("x@p"), out.stream().filter(o -> o.what() instanceof WhoIsContainer).map(OneAgent.Out::to).toList(),
                    "x itself is asked, in a frame sealed to it");
            // x's own answer, authenticated: x is not container, it follows c.
            a.from(x, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c, x));
            assertEquals("c@p", a.layer.containerName());
            assertTrue(a.sent().stream().noneMatch(o -> o.what() instanceof Join));
        }

        @Test
        void aClaimedContainersOwnWordIsFollowed() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry x = other("x", 7009, 2_000);
            OneAgent a = memberOf(c, List.of(x));
            a.from(x, Performative.INFORM, P_DISCOVERY, new ContainerIs(2, x, x));
            assertEquals(List.of("x@p"), a.sent().stream().filter(o -> o.what() instanceof Join).map(OneAgent.Out::to).toList());
        }

        @Test
        void aMemberSayingAnotherIsContainerIsCheckedWithThatOne() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, 10);
            AgentEntry x = other("x", 7009, 2_000);
            OneAgent a = memberOf(c, List.of(x, y));
            a.from(y, Performative.INFORM, P_DISCOVERY, new ContainerIs(99, x, y));
            List<OneAgent.Out> out = a.sent();
            assertTrue(out.stream().noneMatch(o -> o.what() instanceof Join), out.toString());
            assertEquals(1, out.stream().filter(o -> o.what() instanceof WhoIsContainer && o.to().equals("x@p")).count());
            a.from(y, Performative.INFORM, P_DISCOVERY, new ContainerIs(99, x, y));
            assertTrue(a.sent().isEmpty(), "asked once a period, however often it is claimed");
        }

        @Test
        void aCopyOfAListNobodyAskedForIsRefused() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, 10);
            OneAgent a = memberOf(c, List.of(y));
            AgentEntry ghost = other("ghost", 7100, 0);
            a.from(y, Performative.INFORM_REF, P_LAL, new PlatformMessage.LalCopy(1, 9, "c@p",
                    Page.of(0, 1, body(List.of(c, y, ghost)))));
            assertTrue(a.layer.agents().stream().noneMatch(e -> e.name().equals("ghost@p")),
                    "only the container distributes lists: a member cannot list a ghost it speaks for");
            assertEquals(1, a.h.drops().get("unsolicited"));
        }

        @Test
        void aForgedClaimDoesNotMakeAContainerStepDown() {
            AgentEntry m1 = other("m1", 7002, -10);
            OneAgent c = containerWith(m1);
            AgentEntry x = other("x", 7009, 2_000);
            c.fromAny(x, Performative.INFORM, P_DISCOVERY, new ContainerIs(99, x, x));
            assertEquals(Role.CONTAINER, c.role());
            assertTrue(c.sent().stream().noneMatch(o -> o.what() instanceof ContainerIs && ((ContainerIs) o.what()).container().name().equals("x@p")),
                    "it tells its members nothing of x");
        }

        @Test
        void aMessageInAnotherAgentsNameIsAMasquerade() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, 10);
            OneAgent a = memberOf(c, List.of(y));
            // y, a member, sends an alive in its container's name with a later term.
            a.from(y, Performative.INFORM, P_MAINTENANCE, new Alive(5, 9, 40, 250, c));
            assertEquals(1, a.h.drops().get("masquerade") + a.h.drops().get("malformed-platform"), a.h.drops().toString());
            assertEquals("c@p", a.layer.containerName());
            assertTrue(a.sent().isEmpty());
            // ... answers discovery in c's name ...
            long before = a.h.drops().get("masquerade");
            a.from(y, Performative.INFORM, P_DISCOVERY, new ContainerIs(1, c, c));
            assertEquals(before + 1, a.h.drops().get("masquerade"), a.h.drops().toString());
            // ... and joins a stranger to the LAL of its container.
            OneAgent container = containerWith(y);
            container.from(y, Performative.INFORM_REF, P_LAL, new Join(1, other("ghost", 7100, 0)));
            assertEquals(1, container.h.drops().get("masquerade") + container.h.drops().get("malformed-platform"));
            assertTrue(container.layer.agents().stream().noneMatch(e -> e.name().equals("ghost@p")));
        }
    }

    /** Membership control: application messages only from agents the lists name. */
    @Nested
    class Members {

        private static void say(OneAgent a, AgentEntry from, String text) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.setSender(from.aid());
            m.addReceiver(a.self.aid());
            m.setContent(text);
            a.h.receiveUp(Envelope.outgoing(m, a.self.aid(), null));
        }

        private static List<String> delivered(OneAgent a) {
            List<String> out = new ArrayList<>();
            for (Envelope e = a.h.pollUp(); e != null; e = a.h.pollUp()) {
                out.add(e.message().getContent());
            }
            return out;
        }

        @Test
        void aListedAgentsMessageGoesUpAtOnce() {
            AgentEntry c = other("c", 7002, 1_000);
            AgentEntry y = other("y", 7003, 10);
            OneAgent a = memberOf(c, List.of(y));
            say(a, y, "hello");
            assertEquals(List.of("hello"), delivered(a));
        }

        @Test
        void aKeyHolderThatNeverJoinedReachesNobody() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            AgentEntry mallory = other("mallory", 7066, 10);
            for (int i = 0; i < 3; i++) {
                say(a, mallory, "forged " + i);
            }
            assertEquals(List.of(), delivered(a), "it waits for the lists to name mallory");
            a.advance(MembershipGate.WAIT_MS);
            assertEquals(List.of(), delivered(a));
            assertEquals(3, a.h.drops().get("not-member"), a.h.drops().toString());
        }

        @Test
        void anAgentThatJustJoinedIsHeardOnceTheListNamesItInTheOrderItSpoke() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            AgentEntry carol = other("carol", 7004, -5);
            say(a, carol, "one");
            say(a, carol, "two");
            assertEquals(List.of(), delivered(a), "the container's new list is still on its way");
            a.advance(100);
            a.from(c, Performative.INFORM_REF, P_LAL, new LalPage(1, 3, 40, 250,
                    Page.of(0, 1, body(List.of(c, a.self, carol)))));
            say(a, carol, "three");
            assertEquals(List.of("one", "two", "three"), delivered(a));
            assertEquals(0, a.h.drops().get("not-member"));
        }

        @Test
        void aFloodFromStrangersHoldsAtMostTheLimit() {
            AgentEntry c = other("c", 7002, 1_000);
            OneAgent a = memberOf(c, List.of());
            for (int i = 0; i < MembershipGate.MAX_HELD + 100; i++) {
                say(a, other("s" + i, 8000 + i, 0), "x");
            }
            assertEquals(100, a.h.drops().get("not-member"), "the eldest go when the limit is reached");
            a.advance(MembershipGate.WAIT_MS);
            assertEquals(MembershipGate.MAX_HELD + 100, a.h.drops().get("not-member"));
            assertEquals(List.of(), delivered(a));
        }
    }

    @Nested
    class Relay {

        /** A gateway that keeps what it is given to carry out. */
        final class Kept implements Gateway {
            final List<io.concord.core.acl.AclMessage> out = new ArrayList<>();

            @Override
            public void start(GatewayContext context) {
            }

            @Override
            public void stop() {
            }

            @Override
            public boolean reaches(io.concord.core.acl.AID foreign) {
                return true;
            }

            @Override
            public void sendOut(io.concord.core.acl.AclMessage message, io.concord.core.acl.AID receiver) {
                out.add(message);
            }

            @Override
            public List<String> addresses() {
                return List.of("http://127.0.0.1:7779/acc");
            }
        }

        private PlatformMessage.RelayOut relay(String sender) {
            io.concord.core.acl.AclMessage inner = new io.concord.core.acl.AclMessage(Performative.REQUEST);
            inner.setSender(io.concord.core.acl.AID.local(sender, OneAgent.PLATFORM));
            inner.addReceiver(new io.concord.core.acl.AID("j@jade", "http://127.0.0.1:7778/acc"));
            inner.setContent("hello");
            return new PlatformMessage.RelayOut("j@jade", "http://127.0.0.1:7778/acc",
                    io.concord.core.codec.StringAclCodec.INSTANCE.encodeToString(inner));
        }

        @Test
        void theContainerCarriesOutWhatAMemberRelaysInItsOwnName() {
            Kept g = new Kept();
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), g);
            AgentEntry m = other("m", 7002, -10);
            c.from(m, Performative.INFORM, Protocol.P_SERVICES, relay("m"));
            assertEquals(1, g.out.size());
            assertEquals("m@p", g.out.get(0).getSender().name());
        }

        /** A seeking agent with messages to foreign agents, sent from above as an agent sends them. */
        private OneAgent seekingWith(Kept g, AclMessage... ms) {
            OneAgent a = new OneAgent("a", 7001, PlatformConfig.defaults(), g, 7002);
            a.sent();
            for (AclMessage m : ms) {
                a.h.sendDown(Envelope.outgoing(m, m.getReceivers().get(0), null));
            }
            return a;
        }

        private AclMessage toJade(String content) {
            AclMessage m = new AclMessage(Performative.QUERY_REF);
            m.setSender(io.concord.core.acl.AID.local("a", OneAgent.PLATFORM));
            m.addReceiver(new io.concord.core.acl.AID("j@jade", "http://127.0.0.1:7778/acc"));
            m.setContent(content);
            return m;
        }

        @Test
        void aMessageToAForeignAgentWaitsForTheElectionAndGoesToTheContainerOnceItIsKnown() throws Exception {
            OneAgent a = seekingWith(new Kept(), toJade("one"), toJade("two"));
            assertTrue(a.sent().isEmpty(), "no container to carry it yet");
            assertNull(a.h.pollUp(), "and no FAILURE: the election ends in a moment");
            AgentEntry c = other("c", 7002, 1_000);
            a.from(c, Performative.INFORM, P_DISCOVERY, new ContainerIs(3, c, null));
            a.from(c, Performative.CONFIRM, P_LAL, new Joined(3, 40, 250, c));
            assertEquals(Role.MEMBER, a.role());
            List<String> relayed = new ArrayList<>();
            for (OneAgent.Out o : a.sent()) {
                if (o.what() instanceof PlatformMessage.RelayOut r) {
                    assertEquals("c@p", o.to());
                    relayed.add(io.concord.core.codec.StringAclCodec.INSTANCE.decode(r.acl()).getContent());
                }
            }
            assertEquals(List.of("one", "two"), relayed, "both, in the order sent");
            assertEquals(0, a.h.drops().total());
        }

        @Test
        void aMessageToAForeignAgentThatNoContainerCanCarryGetsTheFipaFailureAfterTheWait() {
            // Its neighbour never answers, and it asks for longer than the wait: nobody is elected.
            OneAgent a = new OneAgent("a", 7001, new PlatformConfig(1_000, 3, 60, 40, 500, 3, 60, 4, 5, 3_000), new Kept(), 7002);
            a.h.sendDown(Envelope.outgoing(toJade("one"), toJade("one").getReceivers().get(0), null));
            a.advance(ContainerLayer.CONTAINER_WAIT_MS - 1);
            assertEquals(Role.SEEKING, a.role());
            assertNull(a.h.pollUp(), "not before the wait");
            a.advance(1);
            Envelope f = a.h.pollUp();
            assertEquals(Performative.FAILURE, f.message().getPerformative());
            assertTrue(f.message().getContent().contains("no container"), f.message().getContent());
            assertEquals(1, a.h.drops().get("no-container"));
        }

        @Test
        void aMemberCannotRelayAMessageInAnotherAgentsName() {
            Kept g = new Kept();
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), g);
            AgentEntry m = other("m", 7002, -10);
            c.from(m, Performative.INFORM, Protocol.P_SERVICES, relay("victim"));
            assertTrue(g.out.isEmpty(), "carried out in victim's name: " + g.out);
            assertEquals(1, c.h.drops().get("masquerade"));
        }
    }

    /** Fig. 5.12: a host's container and the containers of the other hosts. */
    @Nested
    class Hosts {
        final NetworkConfig net = NetworkConfig.defaults().withBroadcast(false).withSeeds(List.of("127.0.0.2"))
                .withTiming(250, 1_500);

        /** Another host's container. */
        AgentEntry on2(String local) {
            return new AgentEntry(local + "@" + OneAgent.PLATFORM, "udp://127.0.0.2:7001", OneAgent.EPOCH - 5_000, List.of());
        }

        OneAgent container() {
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), net, null);
            assertEquals(Role.CONTAINER, c.role());
            return c;
        }

        @Test
        void aContainerAnnouncesItselfToItsSeedsEachAnnouncementPeriod() {
            OneAgent c = container();
            List<OneAgent.Out> first = c.sent().stream().filter(o -> o.what() instanceof PlatformMessage.Announce).toList();
            assertEquals(1, first.size());
            assertEquals("127.0.0.2", first.get(0).at().host());
            assertEquals(NetworkConfig.DEFAULT_PORT, first.get(0).at().port());
            c.advance(249);
            assertTrue(c.sent(PlatformMessage.Announce.class).isEmpty());
            c.advance(1);
            assertEquals(1, c.sent(PlatformMessage.Announce.class).size());
        }

        /**
         * Alone (no other host's container known), announcements come rarer, up to
         * {@link Federation#ALONE_MAX_PERIODS} periods: a newcomer announces at its period and is
         * heard. Once another host's container is heard, they come at the period again, within one.
         */
        @Test
        void aContainerAloneAnnouncesLessOftenUntilItHearsAnotherHost() {
            OneAgent c = container();
            c.sent();
            List<Long> gaps = announcementGaps(c, 60_000, null);
            List<Long> expected = new ArrayList<>();
            for (int i = 0; i < gaps.size(); i++) {
                expected.add(250L * Math.min(1 << Math.min(i / 4, 16), Federation.ALONE_MAX_PERIODS));
            }
            assertEquals(expected, gaps);
            assertTrue(gaps.size() < 70, "a minute alone (240 at the period), " + gaps.size() + " announcements");
            AgentEntry z = on2("z");
            c.from(z, Performative.INFORM, Protocol.P_NETWORK, new PlatformMessage.Announce(1, "127.0.0.2", 1, z, List.of()));
            c.sent();
            List<Long> known = announcementGaps(c, 3_000, z);
            assertTrue(known.stream().allMatch(g -> g <= 250), "another host known: " + known);
            assertEquals(12, known.size(), "the first within a period, then each period: " + known);
        }

        /**
         * With nobody to announce to (no broadcast address, no seed, no other host known), a
         * container looks again only every {@link Federation#NOBODY_TO_TELL_MS}; a host that
         * contacts it is announced to within a period all the same.
         */
        @Test
        void aContainerWithNobodyToAnnounceToAnswersAHostThatFindsItWithinAPeriod() {
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), NetworkConfig.defaults().withBroadcast(false)
                    .withTiming(250, 1_500), null);
            c.advance(3 * Federation.NOBODY_TO_TELL_MS + 100);
            assertTrue(c.sent(PlatformMessage.Announce.class).isEmpty());
            AgentEntry z = on2("z");
            List<Long> gaps = announcementGaps(c, 2_000, z);
            assertTrue(!gaps.isEmpty() && gaps.stream().allMatch(g -> g <= 500), "once z is heard: " + gaps);
        }

        /** The gaps between the announcements over {@code ms} (the first counted from the start); {@code peer} announcing each 250 ms if given. */
        private List<Long> announcementGaps(OneAgent c, long ms, AgentEntry peer) {
            List<Long> gaps = new ArrayList<>();
            long last = 0;
            for (long t = 1; t <= ms; t++) {
                c.advance(1);
                if (peer != null && t % 250 == 0) {
                    c.from(peer, Performative.INFORM, Protocol.P_NETWORK, new PlatformMessage.Announce(1, "127.0.0.2", 1, peer, List.of()));
                }
                if (!c.sent(PlatformMessage.Announce.class).isEmpty()) {
                    gaps.add(t - last);
                    last = t;
                }
            }
            return gaps;
        }

        @Test
        void theContainerWithTheSmallerNameOpensTheContactTheOtherAsksForOne() {
            OneAgent c = container();
            c.sent();
            AgentEntry z = on2("z");
            c.from(z, Performative.INFORM, Protocol.P_NETWORK, new PlatformMessage.Announce(1, "127.0.0.2", 1, z, List.of()));
            List<PlatformMessage.WhoIsFacilitator> opened = c.sent(PlatformMessage.WhoIsFacilitator.class);
            assertEquals(1, opened.size(), "me@p < z@p: me opens");
            assertEquals(32, opened.get(0).secret().length(), "a 128-bit secret");
            AgentEntry a = on2("a");
            c.from(a, Performative.INFORM, Protocol.P_NETWORK, new PlatformMessage.Announce(1, "127.0.0.3", 1, a, List.of()));
            List<OneAgent.Out> out = c.sent();
            assertTrue(out.stream().anyMatch(o -> o.what() instanceof PlatformMessage.ContactMe && o.to().equals("a@p")), out.toString());
            assertTrue(out.stream().noneMatch(o -> o.what() instanceof PlatformMessage.WhoIsFacilitator), "a@p < me@p: a opens");
        }

        @Test
        void anotherHostsListWithTheAgreedSecretGoesIntoTheGalOfEveryMember() {
            AgentEntry m = other("m", 7002, -10);
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), net, null);
            c.from(m, Performative.INFORM_REF, P_LAL, new Join(1, m));
            c.advance(10);
            c.sent();
            AgentEntry a = on2("a");
            c.from(a, Performative.REQUEST, Protocol.P_NETWORK, new PlatformMessage.WhoIsFacilitator("s3cret", 1, "127.0.0.2", a));
            List<OneAgent.Out> out = c.sent();
            assertTrue(out.stream().anyMatch(o -> o.what() instanceof PlatformMessage.IsFacilitator i && i.secret().equals("s3cret")));
            assertTrue(out.stream().anyMatch(o -> o.what() instanceof PlatformMessage.GalUpdate u && o.to().equals("a@p")
                    && names(u.page().entries()).equals(List.of("m@p", "me@p"))), "our list goes to the other host: " + out);
            AgentEntry b = new AgentEntry("b@p", "udp://127.0.0.2:7002", OneAgent.EPOCH, List.of());
            c.from(a, Performative.INFORM_REF, Protocol.P_NETWORK, new PlatformMessage.GalUpdate("s3cret", 1, 1,
                    PlatformMessage.Page.of(0, 1, body(List.of(a, b)))));
            assertEquals(List.of("a@p", "b@p"), names(List.copyOf(c.layer.globalAgents())));
            c.advance(ContainerRole.GAL_PUSH_DELAY_MS); // changes arriving together go out together
            assertTrue(c.sent().stream().anyMatch(o -> o.what() instanceof PlatformMessage.GalPage && o.to().equals("m@p")),
                    "the member gets the GAL");
        }

        @Test
        void aListWithoutTheAgreedSecretIsDiscardedCountedAndItsSenderTold() {
            OneAgent c = container();
            AgentEntry a = on2("a");
            c.from(a, Performative.REQUEST, Protocol.P_NETWORK, new PlatformMessage.WhoIsFacilitator("s3cret", 1, "127.0.0.2", a));
            c.sent();
            c.from(a, Performative.INFORM_REF, Protocol.P_NETWORK, new PlatformMessage.GalUpdate("guess", 1, 1,
                    PlatformMessage.Page.of(0, 1, body(List.of(a, on2("x"))))));
            assertTrue(c.layer.globalAgents().isEmpty());
            assertEquals(1, c.h.drops().get("bad-secret"));
            assertEquals(1, c.sent(PlatformMessage.UnknownSecret.class).size());
        }

        @Test
        void aHostSilentForTheHostTimeoutLeavesTheGal() {
            OneAgent c = container();
            AgentEntry a = on2("a");
            c.from(a, Performative.REQUEST, Protocol.P_NETWORK, new PlatformMessage.WhoIsFacilitator("s3cret", 1, "127.0.0.2", a));
            c.from(a, Performative.INFORM_REF, Protocol.P_NETWORK, new PlatformMessage.GalUpdate("s3cret", 1, 1,
                    PlatformMessage.Page.of(0, 1, body(List.of(a)))));
            assertEquals(List.of("a@p"), names(List.copyOf(c.layer.globalAgents())));
            c.advance(1_500);
            assertEquals(List.of("a@p"), names(List.copyOf(c.layer.globalAgents())), "not before the timeout");
            c.advance(251);
            assertTrue(c.layer.globalAgents().isEmpty());
        }
    }

    /** Hole 6: what the network can make a container or a seeker hold is bounded, each limit counted. */
    @Nested
    class Bounds {
        final NetworkConfig net = NetworkConfig.defaults().withBroadcast(false).withSeeds(List.of("127.0.0.2"))
                .withTiming(250, 1_500);

        @Test
        void aFloodOfQuestionsInNewNamesMakesASeekerHoldAtMostTheCandidateLimit() {
            OneAgent a = new OneAgent("a", 7001, 7002);
            a.sent();
            int n = PlatformState.MAX_SEEKERS + 976;
            for (int i = 0; i < n; i++) {
                AgentEntry s = other("s" + i, 20_000 + i, -1_000);
                a.fromAny(s, Performative.QUERY_REF, P_DISCOVERY, new WhoIsContainer(0, s));
            }
            assertEquals(n, a.sent(Seeking.class).size(), "every question is answered");
            assertEquals(976, a.h.drops().get("seekers-limit"), "the askers past the limit are not held, and counted");
            a.from(other("b", 7002, -500), Performative.INFORM, P_DISCOVERY, new Seeking(0, 0, other("b", 7002, -500)));
            assertEquals(Role.CONTAINER, a.role(), "a is the eldest");
            assertEquals(PlatformState.MAX_SEEKERS, a.sent(ContainerIs.class).size(),
                    "the new container tells the candidates it holds, and no more");
        }

        @Test
        void announcementsOfManyHostsMakeAContainerKnowAtMostTheHostLimitAndKeepItsContacts() {
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), net, null);
            AgentEntry a = new AgentEntry("a@p", "udp://127.0.0.2:7001", OneAgent.EPOCH - 5_000, List.of());
            c.from(a, Performative.REQUEST, Protocol.P_NETWORK, new PlatformMessage.WhoIsFacilitator("s3cret", 1, "127.0.0.2", a));
            c.from(a, Performative.INFORM_REF, Protocol.P_NETWORK, new PlatformMessage.GalUpdate("s3cret", 1, 1,
                    Page.of(0, 1, body(List.of(a)))));
            c.sent();
            // A key holder announces a host that knows 1,000 more: each would be a facilitator to
            // announce to, and to contact, every period.
            List<AgentEntry> made = new ArrayList<>();
            for (int i = 0; i < 1_000; i++) {
                made.add(new AgentEntry("z" + i + "@p", "udp://10.200." + (1 + i / 200) + "." + (1 + i % 200) + ":7001",
                        OneAgent.EPOCH, List.of()));
            }
            AgentEntry z = new AgentEntry("zz@p", "udp://10.200.9.9:7001", OneAgent.EPOCH, List.of());
            c.fromAny(z, Performative.INFORM, Protocol.P_NETWORK, new PlatformMessage.Announce(1, "10.200.9.9", 1, z, made));
            assertEquals(Federation.MAX_FACILITATORS, c.layer.federation().facilitators().size(), "no more hosts known than the limit");
            assertTrue(c.h.drops().get("facilitator-limit") >= 1_000 + 1 - (Federation.MAX_FACILITATORS - 1));
            assertTrue(c.layer.federation().facilitators().containsKey("a@p"), "the host in contact is never the one forgotten");
            assertEquals(List.of("a@p"), names(List.copyOf(c.layer.globalAgents())));
            c.sent();
            c.advance(250);
            long announced = c.sent().stream().filter(o -> o.what() instanceof PlatformMessage.Announce).count();
            assertEquals(1 + Federation.MAX_FACILITATORS, announced, "an announcement to the seed and to each host known");
        }

        @Test
        void aListWhosePagesGrowPastTheLimitIsDroppedAndCounted() {
            OneAgent c = new OneAgent("me", 7001, PlatformConfig.defaults(), net, null);
            AgentEntry a = new AgentEntry("a@p", "udp://127.0.0.2:7001", OneAgent.EPOCH - 5_000, List.of());
            c.from(a, Performative.REQUEST, Protocol.P_NETWORK, new PlatformMessage.WhoIsFacilitator("s3cret", 1, "127.0.0.2", a));
            // A version announced as 10,000 pages, each of some 8 KiB, whose last page never comes.
            List<AgentEntry> page = new ArrayList<>();
            for (int i = 0; i < 60; i++) {
                page.add(new AgentEntry("agent-with-a-long-name-" + "x".repeat(60) + i + "@p", "udp://127.0.0.2:" + (7002 + i),
                        OneAgent.EPOCH, List.of()));
            }
            String text = body(page);
            int sent = 0;
            while ((long) sent * text.length() <= PageAssembler.MAX_BYTES) {
                c.from(a, Performative.INFORM_REF, Protocol.P_NETWORK, new PlatformMessage.GalUpdate("s3cret", 1, 1,
                        Page.of(sent, 10_000, text)));
                sent++;
            }
            assertEquals(1, c.h.drops().get("list-too-large"), "the pages held past " + PageAssembler.MAX_BYTES + " bytes are dropped");
            assertTrue(c.layer.globalAgents().isEmpty());
            // The next version is taken whole.
            c.from(a, Performative.INFORM_REF, Protocol.P_NETWORK, new PlatformMessage.GalUpdate("s3cret", 1, 2,
                    Page.of(0, 1, body(List.of(a)))));
            assertEquals(List.of("a@p"), names(List.copyOf(c.layer.globalAgents())));
        }
    }
}
