package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A platform on two loops, real UDP, class 7: each agent runs on one thread for life; two agents of
 * one loop talk in memory on that loop, two of different loops in memory through the receiver's
 * loop's queue, both at once.
 */
class PlatformLoopsTest {
    static final String RANGE = "7481-7500";

    @TempDir
    Path home;

    /** Pings its partner N times, noting every thread its behaviour ran on. */
    static final class Pinger extends Agent {
        final Set<Thread> threads = ConcurrentHashMap.newKeySet();
        final AtomicLong rounds = new AtomicLong();
        volatile AID partner;

        @Override
        protected void setup() {
            threads.add(Thread.currentThread());
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    threads.add(Thread.currentThread());
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    if (m.getPerformative() == Performative.REQUEST) {
                        AclMessage r = m.createReply();
                        r.setPerformative(Performative.INFORM);
                        send(r);
                    } else if (rounds.incrementAndGet() < 2_000) {
                        ping();
                    }
                }
            });
        }

        void ping() {
            AclMessage r = new AclMessage(Performative.REQUEST);
            r.addReceiver(partner);
            r.setContent("ping");
            send(r);
        }
    }

    @Test
    void agentsOfTwoLoopsRunOnTwoThreadsAndTalkInMemoryOnOneAndAcross() throws Exception {
        System.setProperty("concord.home", home.toString());
        try (Platform p = Platform.builder().name("loops" + ProcessHandle.current().pid()).ports(PortRange.parse(RANGE))
                .profile(Profile.CLASS_7).loops(2).build()) {
            assertEquals(2, p.loops());
            Pinger a = new Pinger();
            Pinger b = new Pinger();
            Pinger c = new Pinger();
            Pinger d = new Pinger();
            AID aid = p.startAgentOn(0, "a", a);
            AID bid = p.startAgentOn(0, "b", b);
            AID cid = p.startAgentOn(0, "c", c);
            AID did = p.startAgentOn(1, "d", d);
            a.partner = bid;
            b.partner = aid;
            c.partner = did;
            d.partner = cid;
            p.runtime().execute(a::ping);   // a and b: one loop
            p.runtime().execute(c::ping);   // c and d: two loops
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while ((a.rounds.get() < 2_000 || c.rounds.get() < 2_000) && System.nanoTime() < end) {
                Thread.sleep(20);   // a poll of the rounds with a deadline
            }
            assertEquals(2_000, a.rounds.get(), "the pair on one loop");
            assertEquals(2_000, c.rounds.get(), "the pair across two loops");
            for (Pinger x : new Pinger[] {a, b, c, d}) {
                assertEquals(1, x.threads.size(), "one thread for life: " + x.threads);
            }
            assertEquals(a.threads, c.threads, "a and c on loop 0");
            assertNotEquals(c.threads, d.threads, "c and d on two loops, two threads");
            // a, b and c hand over on loop 0 (a and b within it, c across to d), d across to c.
            assertTrue(p.runtimes().get(0).handedOver() >= 6_000, "a and b, and c to d, in memory: " + p.runtimes().get(0).handedOver());
            assertTrue(p.runtimes().get(1).handedOver() >= 2_000, "d to c in memory, across loops: " + p.runtimes().get(1).handedOver());
        }
    }

    @Test
    void agentsArePlacedRoundRobinAndAWrongLoopOrCountIsRefused() {
        System.setProperty("concord.home", home.toString());
        assertThrows(IllegalArgumentException.class, () -> Platform.builder().loops(0));
        try (Platform p = Platform.builder().name("rr" + ProcessHandle.current().pid()).ports(PortRange.parse(RANGE)).loops(3).build()) {
            Pinger[] ps = new Pinger[6];
            for (int i = 0; i < ps.length; i++) {
                ps[i] = new Pinger();
                p.startAgent("p" + i, ps[i]);
            }
            for (int i = 0; i < 3; i++) {
                assertEquals(ps[i].runtime(), ps[i + 3].runtime(), "agent " + i + " and " + (i + 3) + " share a loop");
                assertNotEquals(ps[i].runtime(), ps[(i + 1) % 3].runtime());
            }
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> p.startAgentOn(3, "x", new Pinger()));
            assertTrue(e.getMessage().contains("0 to 2"), e.getMessage());
        }
    }
}
