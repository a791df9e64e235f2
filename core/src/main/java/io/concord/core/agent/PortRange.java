package io.concord.core.agent;

import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.net.Network;
import io.concord.core.net.Receiver;
import io.concord.core.net.Transport;

import java.util.List;

/**
 * The port range of the port-binding discovery (dissertation fig. 5.6): an agent tries to bind the
 * base port, then the next; a port it cannot bind is held by a potential agent. The first free port
 * becomes its own; it then probes a window of ports past it for more potential agents (holes left
 * by agents that stopped), binding and releasing each.
 *
 * @param base   the first port (7001 by default)
 * @param count  how many ports the range holds
 * @param window how many ports past its own an agent probes
 */
public record PortRange(int base, int count, int window) {
    public static final int DEFAULT_BASE = 7001;
    public static final int DEFAULT_COUNT = 200;
    public static final int DEFAULT_WINDOW = 10;

    public PortRange {
        if (base < 1 || count < 1 || (long) base + count - 1 > 65535) {
            throw new IllegalArgumentException("a port range must lie within 1..65535 and hold at least one port, got "
                    + base + " and " + count + " ports");
        }
        if (window < 0) {
            throw new IllegalArgumentException("the probe window must be >= 0, got " + window);
        }
    }

    /** 7001 and the next 199 ports, probing 10 past the agent's own. */
    public static PortRange defaults() {
        return new PortRange(DEFAULT_BASE, DEFAULT_COUNT, DEFAULT_WINDOW);
    }

    /** From {@code first} to {@code last}, both included, with the default probe window. */
    public static PortRange of(int first, int last) {
        if (last < first) {
            throw new IllegalArgumentException("the port range " + first + "-" + last + " ends before it starts");
        }
        return new PortRange(first, last - first + 1, DEFAULT_WINDOW);
    }

    /** Parses {@code 7001-7200} or {@code 7001} (that port and the default count). */
    public static PortRange parse(String text) {
        String s = text.trim();
        try {
            int dash = s.indexOf('-');
            if (dash < 0) {
                return new PortRange(Integer.parseInt(s), DEFAULT_COUNT, DEFAULT_WINDOW);
            }
            return of(Integer.parseInt(s.substring(0, dash).trim()), Integer.parseInt(s.substring(dash + 1).trim()));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("a port range is written 7001-7200, got '" + text + "'");
        }
    }

    public int last() {
        return base + count - 1;
    }

    /**
     * Binds the first free port and fills {@code held} with the ports found held, below it and in
     * the window past it.
     *
     * @throws IllegalStateException if every port of the range is held, naming the range and how to
     *                               widen it
     */
    public Endpoint bindFirstFree(Network network, Transport transport, String host, Receiver receiver, List<Address> held) {
        Endpoint own = null;
        int p = base;
        for (; p <= last(); p++) {
            own = network.tryBind(transport, host, p, receiver);
            if (own != null) {
                break;
            }
            held.add(new Address(host, p));
        }
        if (own == null) {
            throw new IllegalStateException("the " + transport + " port range " + base + "-" + last() + " on " + host
                    + " is full: all " + count + " ports are held by agents or other programs; widen it "
                    + "(-ports " + base + "-" + Math.min(65535, last() + count) + ", or PortRange.of) or stop some agents");
        }
        int end = Math.min(last(), p + window);
        for (int q = p + 1; q <= end; q++) {
            if (network.isHeld(transport, host, q)) {
                held.add(new Address(host, q));
            }
        }
        return own;
    }

    @Override
    public String toString() {
        return base + "-" + last();
    }
}
