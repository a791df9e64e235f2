package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.observe.ObserverLayer;
import io.concord.testkit.EchoAgent;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * No head-of-line stall: a ping-pong of two agents of this JVM, the ping sniffed by an observer in
 * another JVM (as the console sniffs), on real UDP, class 7. The observer is then stopped (SIGSTOP:
 * a frozen console, a laptop's lid shut) or killed: the frames to it wait, or are dropped and
 * counted, but the ping and the pong go on with their own conversation. So do they with an
 * observer that falls behind (its mailbox full, its window shut) and is then killed.
 */
class GoneObserverTest {
    static final String RANGE = "7461-7480";
    static final int ROUNDS = 3_000;

    @TempDir
    Path home;
    private Process child;
    private Platform platform;

    /** Sends REQUESTs to its pong, one after the other, counting the rounds. */
    static final class Ping extends Agent {
        final AtomicLong rounds = new AtomicLong();
        volatile AID pong;

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    if (m.getPerformative() == Performative.INFORM) {
                        rounds.incrementAndGet();
                        next();
                    }
                }
            });
        }

        void next() {
            AclMessage r = new AclMessage(Performative.REQUEST);
            r.addReceiver(pong);
            r.setContent("ping");
            send(r);
        }
    }

    @AfterEach
    void stop() throws Exception {
        if (child != null) {
            new ProcessBuilder("kill", "-CONT", Long.toString(child.pid())).start().waitFor();
            child.destroyForcibly().waitFor();
        }
        if (platform != null) {
            platform.close();
        }
    }

    private void awaitRounds(Ping ping, long atLeast, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (ping.rounds.get() < atLeast && System.nanoTime() < end) {
            Thread.sleep(20);   // a poll of the rounds with a deadline, not a wait for time to pass
        }
        assertTrue(ping.rounds.get() >= atLeast, what + ": " + ping.rounds.get() + " rounds of " + atLeast);
    }

    /** The observer's next line that starts so, or null if none comes within 20 s of the one before. */
    private static String lineStarting(LinkedBlockingQueue<String> lines, String start) throws InterruptedException {
        String l;
        while ((l = lines.poll(20, TimeUnit.SECONDS)) != null) {
            if (l.startsWith(start)) {
                return l;
            }
        }
        return null;
    }

    private void observedThenGone(String signal, boolean behindFirst) throws Exception {
        String name = "gone" + ProcessHandle.current().pid() + signal.toLowerCase() + (behindFirst ? "behind" : "");
        System.setProperty("concord.home", home.toString());
        platform = Platform.builder().name(name).ports(PortRange.parse(RANGE)).profile(Profile.CLASS_7).build();
        Ping ping = new Ping();
        AID pong = platform.startAgent("pong", new EchoAgent());
        ping.pong = pong;
        AID pingAid = platform.startAgent("ping", ping);

        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // An observer that falls behind has a small mailbox (64): it fills, and the window to it shuts, at once.
        child = new ProcessBuilder(java, "-Dconcord.home=" + home, "-Dconcord.test.mailbox=" + (behindFirst ? 64 : 100_000),
                "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"),
                PlatformChild.class.getName(), name, RANGE, "observer").redirectError(ProcessBuilder.Redirect.INHERIT).start();
        LinkedBlockingQueue<String> lines = new LinkedBlockingQueue<>();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
                String l;
                while ((l = r.readLine()) != null) {
                    lines.add(l);
                }
            } catch (java.io.IOException ignored) {
                // gone
            }
        }, "observer-out");
        reader.setDaemon(true);
        reader.start();
        PrintWriter in = new PrintWriter(child.getOutputStream(), true, StandardCharsets.UTF_8);
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        String l;
        while ((l = lines.poll(1, TimeUnit.SECONDS)) != null || System.nanoTime() < end) {
            if (l != null && l.startsWith("STATE") && l.contains("agents=3")) {
                break;
            }
        }
        in.println("sniff ping");
        assertNotNull(lineStarting(lines, "GOT AGREE"), "the observer sniffs the ping");
        CompletableFuture<Integer> sniffers = new CompletableFuture<>();
        platform.runtime().execute(() -> {
            ping.next();
            sniffers.complete(platform.runtime().layer(pingAid, ObserverLayer.class).sniffers());
        });
        assertEquals(1, sniffers.get(10, TimeUnit.SECONDS));
        awaitRounds(ping, 200, "the ping-pong runs while sniffed");

        if (behindFirst) {
            // The observer takes nothing more from its mailbox (a console whose browser stopped
            // reading, a JVM in a long pause that still acknowledges): it answers, its window shut.
            in.println("deaf");
            assertNotNull(lineStarting(lines, "DEAF"), "the observer stops taking its mailbox");
            long before = ping.rounds.get();
            awaitRounds(ping, before + ROUNDS, "the ping-pong goes on with its observer behind");
            CompletableFuture<Long> refused = new CompletableFuture<>();
            platform.runtime().execute(() -> refused.complete(platform.runtime().drops(pingAid).getOrDefault("receiver-behind", 0L)));
            assertTrue(refused.get(10, TimeUnit.SECONDS) > 0, "the events the observer could not take are refused and counted");
        }
        new ProcessBuilder("kill", "-" + signal, Long.toString(child.pid())).start().waitFor();
        long at = ping.rounds.get();
        // Far more rounds than the flow window (256) and the frames held for one receiver (4,096):
        // each round is two events for the observer that it never acknowledges.
        awaitRounds(ping, at + ROUNDS, "the ping-pong goes on with its observer " + (signal.equals("STOP") ? "stopped" : "killed"));
    }

    @Test
    void aStoppedObserverHoldsBackOnlyItsOwnFrames() throws Exception {
        observedThenGone("STOP", false);
    }

    @Test
    void aKilledObserverHoldsBackNothing() throws Exception {
        observedThenGone("KILL", false);
    }

    /**
     * The console's case: its mailbox full, it answers with its window shut, then it closes.
     * Before, the sniffed agent was paused as long as the observer answered, and for good after.
     */
    @Test
    void anObserverBehindAndThenKilledHoldsBackNothing() throws Exception {
        observedThenGone("KILL", true);
    }
}
