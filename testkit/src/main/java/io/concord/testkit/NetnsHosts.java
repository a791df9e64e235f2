package io.concord.testkit;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Hosts as Linux network namespaces for tests and benchmarks: {@code n} hosts, each with an
 * {@code eth0} on one bridge (in a switch namespace of its own), addressed 10.200.0.11, .12, ...
 * /24, with the route the limited broadcast needs. Nothing is connected to any other network.
 * Needs root and iproute2; {@link #close()} deletes every namespace it made.
 */
public final class NetnsHosts implements AutoCloseable {
    private final String prefix;
    private final List<String> made = new ArrayList<>();

    /**
     * @param prefix a short unique prefix of the namespace names (at most 8 characters)
     * @param hosts  how many hosts
     * @throws IOException naming the command that failed, e.g. when this is not root
     */
    public NetnsHosts(String prefix, int hosts) throws IOException, InterruptedException {
        this.prefix = prefix;
        try {
            String sw = prefix + "sw";
            ip("netns", "add", sw);
            made.add(sw);
            ip("-n", sw, "link", "add", "br0", "type", "bridge");
            ip("-n", sw, "link", "set", "br0", "up");
            for (int i = 1; i <= hosts; i++) {
                String h = namespace(i);
                ip("netns", "add", h);
                made.add(h);
                ip("-n", h, "link", "add", "eth0", "type", "veth", "peer", "name", "s" + i, "netns", sw);
                ip("-n", sw, "link", "set", "s" + i, "master", "br0");
                ip("-n", sw, "link", "set", "s" + i, "up");
                ip("-n", h, "addr", "add", address(i) + "/24", "dev", "eth0");
                ip("-n", h, "link", "set", "eth0", "up");
                ip("-n", h, "link", "set", "lo", "up");
                ip("-n", h, "route", "add", "255.255.255.255/32", "dev", "eth0");
            }
        } catch (IOException | InterruptedException e) {
            close();
            throw e;
        }
    }

    /** The namespace of host i (1-based). */
    public String namespace(int i) {
        return prefix + "h" + i;
    }

    /** The address of host i (1-based): 10.200.0.(10 + i). */
    public static String address(int i) {
        return "10.200.0." + (10 + i);
    }

    /** The command prefix that runs a program on host i: {@code ip netns exec <ns>}. */
    public List<String> exec(int i) {
        return List.of("ip", "netns", "exec", namespace(i));
    }

    /** Takes host i's link down (at the bridge) or up again. */
    public void link(int i, boolean up) throws IOException, InterruptedException {
        ip("-n", prefix + "sw", "link", "set", "s" + i, up ? "up" : "down");
    }

    private static void ip(String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add("ip");
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(30, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IOException(String.join(" ", cmd) + " failed (exit " + (p.isAlive() ? "timeout" : p.exitValue())
                    + "): " + out.trim());
        }
    }

    @Override
    public void close() {
        for (int i = made.size() - 1; i >= 0; i--) {
            try {
                ip("netns", "del", made.get(i));
            } catch (IOException e) {
                // already gone
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        made.clear();
    }
}
