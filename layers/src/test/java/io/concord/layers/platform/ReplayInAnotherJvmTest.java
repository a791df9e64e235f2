package io.concord.layers.platform;

import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A seed replays in another JVM, not only in this one: the same network simulation (hosts, their
 * containers, facilitators exchanging lists under a secret, a forger) run here and in a child JVM
 * gives the same trace, bit for bit. Two things broke that: a facilitator's secret taken from an
 * unseeded SecureRandom (now the runtime's secret source, its seed in a simulation), and
 * collections whose order is salted per JVM run going on the wire.
 */
class ReplayInAnotherJvmTest {

    /** Runs one seed of the network simulation and prints its trace hash (the child's main). */
    public static void main(String[] args) {
        long seed = Long.parseLong(args[0]);
        String failure = NetworkSimulationTest.scenario(seed);
        System.out.println(failure == null ? "hash " + Long.toHexString(NetworkSimulationTest.lastTraceHash) : "failed " + failure);
    }

    @Test
    void aNetworkSimulationSeedGivesTheSameTraceInAnotherJvm() throws Exception {
        for (long seed : new long[] {1, 4}) {
            assertNull(NetworkSimulationTest.scenario(seed), "seed " + seed + " converges");
            String here = "hash " + Long.toHexString(NetworkSimulationTest.lastTraceHash);
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process p = new ProcessBuilder(java, "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"),
                    ReplayInAnotherJvmTest.class.getName(), Long.toString(seed))
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            String there = null;
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) {
                    if (line.startsWith("hash ") || line.startsWith("failed ")) {
                        there = line;
                    }
                }
            }
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child ends");
            assertEquals(here, there, "seed " + seed + ": this JVM's trace and the child's");
        }
    }
}
