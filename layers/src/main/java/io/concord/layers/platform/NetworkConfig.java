package io.concord.layers.platform;

import io.concord.core.net.Address;

import java.util.ArrayList;
import java.util.List;

/**
 * Network discovery between the containers of several hosts (dissertation fig. 5.12): each
 * container announces itself every {@code announcePeriodMs}, by UDP broadcast on the discovery port
 * (the subnet broadcast of its interface and 255.255.255.255) and by unicast to the seeds; a host
 * not heard for {@code hostTimeoutMs} leaves the Global Agent List. Nothing is broadcast from a
 * loopback address.
 *
 * @param discoveryPort    the UDP port every container listens on (shared by the platforms of a host)
 * @param seeds            containers' hosts to contact by unicast where broadcast does not pass
 *                         ({@code host:port}, the port being their discovery port)
 * @param broadcast        false to announce to the seeds only (routed networks, class 7 across the Internet)
 * @param announcePeriodMs how often a container announces itself
 * @param hostTimeoutMs    the silence after which a host's agents leave the GAL
 */
public record NetworkConfig(int discoveryPort, List<Address> seeds, boolean broadcast, long announcePeriodMs,
                            long hostTimeoutMs) {
    public static final int DEFAULT_PORT = 7000;

    public NetworkConfig {
        if (discoveryPort < 1 || discoveryPort > 65535) {
            throw new IllegalArgumentException("the discovery port must be 1..65535, got " + discoveryPort);
        }
        seeds = List.copyOf(seeds);
        if (announcePeriodMs <= 0 || hostTimeoutMs < 2 * announcePeriodMs) {
            throw new IllegalArgumentException("announcePeriodMs must be > 0 and hostTimeoutMs at least twice it, got "
                    + announcePeriodMs + " and " + hostTimeoutMs);
        }
    }

    /** Port 7000, broadcast, no seeds, an announcement every 250 ms, a host gone after 1.5 s of silence. */
    public static NetworkConfig defaults() {
        return new NetworkConfig(DEFAULT_PORT, List.of(), true, 250, 1_500);
    }

    /** These seeds besides broadcast; each written {@code host} or {@code host:port}. */
    public NetworkConfig withSeeds(List<String> hostPorts) {
        List<Address> out = new ArrayList<>();
        for (String s : hostPorts) {
            String t = s.trim();
            Address a = t.contains(":") ? Address.parse(t) : new Address(t, discoveryPort);
            if (a == null) {
                throw new IllegalArgumentException("a seed is written host or host:port, got '" + s + "'");
            }
            out.add(a);
        }
        return new NetworkConfig(discoveryPort, out, broadcast, announcePeriodMs, hostTimeoutMs);
    }

    public NetworkConfig withPort(int port) {
        return new NetworkConfig(port, seeds, broadcast, announcePeriodMs, hostTimeoutMs);
    }

    public NetworkConfig withBroadcast(boolean on) {
        return new NetworkConfig(discoveryPort, seeds, on, announcePeriodMs, hostTimeoutMs);
    }

    public NetworkConfig withTiming(long announceMs, long timeoutMs) {
        return new NetworkConfig(discoveryPort, seeds, broadcast, announceMs, timeoutMs);
    }
}
