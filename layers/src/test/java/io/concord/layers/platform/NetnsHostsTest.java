package io.concord.layers.platform;

import io.concord.layers.security.PlatformKey;
import io.concord.testkit.NetnsHosts;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * Three hosts as network namespaces on a bridge (10.200.0.0/24, nothing else), two agents per host,
 * each in a JVM of its own, class 7, discovery by broadcast: everyone reaches everyone by name; a
 * DF search on one host finds a service registered on another; kill -9 of a host's container: the
 * others update their GAL and the host re-joins under its new container; a host's link goes down
 * and up again: the platform converges. Needs root and iproute2 (CI runs as root); where
 * namespaces cannot be made, it fails and says why.
 */
class NetnsHostsTest {
    static final String PLATFORM = "hosts";
    static final String PREFIX = "cc" + (ProcessHandle.current().pid() % 100_000);

    @TempDir
    Path home;

    final Map<String, PlatformProcessesTest.Child> children = new LinkedHashMap<>();
    final Map<String, String> hostOf = new LinkedHashMap<>();

    private NetnsHosts hosts;

    private void buildHosts(int n) throws Exception {
        try {
            hosts = new NetnsHosts(PREFIX, n);
        } catch (IOException e) {
            fail("cannot create network namespaces, so the hosts of this test cannot exist; it needs root and "
                    + "iproute2 ('ip'), as CI has: " + e.getMessage());
        }
    }

    @AfterEach
    void tearDown() throws Exception {
        for (PlatformProcessesTest.Child c : children.values()) {
            c.process.destroyForcibly();
        }
        for (PlatformProcessesTest.Child c : children.values()) {
            c.process.waitFor(10, TimeUnit.SECONDS);
        }
        if (hosts != null) {
            hosts.close();
        }
    }

    private void spawn(int host, String name) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(hosts.exec(host));
        cmd.addAll(List.of(java, "-Dconcord.home=" + home, "-XX:TieredStopAtLevel=1", "-Xss512k", "-cp",
                System.getProperty("java.class.path"), PlatformChild.class.getName(), PLATFORM, "7001-7100", name,
                NetnsHosts.address(host)));
        Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        children.put(name, new PlatformProcessesTest.Child(name, p));
        hostOf.put(name, "h" + host);
    }

    /** Waits until every child's last state satisfies the condition. */
    private void await(String what, Predicate<PlatformProcessesTest.Child> ok) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            if (children.values().stream().allMatch(ok)) {
                return;
            }
            // A poll of the children's reports with a deadline, not a wait for time to pass.
            Thread.sleep(20);
        }
        StringBuilder b = new StringBuilder();
        children.forEach((n, c) -> b.append(n).append(" on ").append(hostOf.get(n)).append(": ").append(c.state).append('\n'));
        fail("not within 60 s: " + what + "\n" + b);
    }

    private static boolean settled(PlatformProcessesTest.Child c, int agents, int gal) {
        return !c.field("role").equals("SEEKING") && !c.field("container").equals("null")
                && c.field("agents").equals(String.valueOf(agents)) && c.field("gal").equals(String.valueOf(gal));
    }

    private void allPairsByName() throws InterruptedException {
        String tag = "t" + System.nanoTime();
        for (String from : children.keySet()) {
            for (String to : children.keySet()) {
                if (!from.equals(to)) {
                    children.get(from).in.println("send " + to + " " + tag + "-" + from);
                }
            }
        }
        for (String to : children.keySet()) {
            for (String from : children.keySet()) {
                if (!from.equals(to)) {
                    String want = "GOT REQUEST from " + from + " " + tag + "-" + from;
                    assertTrue(awaitSeen(to, want, 30_000), () -> to + " never got: " + want + "\n" + from + " printed: "
                            + children.get(from).all + "\n" + to + " printed: " + children.get(to).all);
                }
            }
        }
    }

    /** True once the child has printed the line (now or before), within the time given. */
    private boolean awaitSeen(String child, String line, long ms) throws InterruptedException {
        PlatformProcessesTest.Child c = children.get(child);
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms);
        while (!c.all.contains(line)) {
            if (System.nanoTime() > end) {
                return false;
            }
            c.lines.poll(20, TimeUnit.MILLISECONDS); // wakes on the child's next line
        }
        return true;
    }

    @Test
    void threeHostsFindEachOtherByBroadcastAndSurviveCrashesAndLinkLoss() throws Exception {
        buildHosts(3);
        PlatformKey.loadOrCreate(home.resolve("platform.key"));
        for (int h = 1; h <= 3; h++) {
            spawn(h, "n" + h + "a");
            spawn(h, "n" + h + "b");
        }
        await("two agents per host, four in each GAL", c -> settled(c, 2, 4));
        allPairsByName();

        // The yellow pages span the hosts.
        children.get("n2a").in.println("register weather");
        assertTrue(awaitSeen("n2a", "REGISTERED weather", 30_000));
        boolean found = false;
        for (int i = 0; i < 40 && !found; i++) {
            children.get("n1b").in.println("search weather");
            String l = children.get("n1b").awaitLine(x -> x.startsWith("FOUND weather"), 5_000);
            found = l != null && l.contains("n2a@" + PLATFORM);
        }
        assertTrue(found, "a DF search on host 1 never found the service registered on host 2");

        // kill -9 of host 3's container.
        String victim = children.keySet().stream().filter(n -> hostOf.get(n).equals("h3")
                && children.get(n).field("role").equals("CONTAINER")).findFirst().orElseThrow();
        PlatformProcessesTest.Child dead = children.remove(victim);
        dead.process.destroyForcibly().waitFor();
        await("host 3 re-joined under its new container", c -> hostOf.get(c.name).equals("h3")
                ? settled(c, 1, 4) && c.field("role").equals("CONTAINER") : settled(c, 2, 3));

        // Host 2's link goes down (the others drop its agents), then up (they come back).
        hosts.link(2, false);
        await("host 2 is gone for the others", c -> switch (hostOf.get(c.name)) {
            case "h1" -> settled(c, 2, 1);
            case "h3" -> settled(c, 1, 2);
            default -> settled(c, 2, 0);
        });
        hosts.link(2, true);
        await("host 2 is back", c -> hostOf.get(c.name).equals("h3") ? settled(c, 1, 4) : settled(c, 2, 3));
        allPairsByName();
    }
}
