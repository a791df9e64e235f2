package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.net.Address;

import java.util.Comparator;
import java.util.List;
import java.util.Objects;

/**
 * One line of the Local Agent List (the white pages, with each agent's yellow-pages services):
 * who the agent is, where it receives, when it started, and what it offers.
 *
 * @param name     the full name, {@code local@platform}
 * @param address  its transport address, {@code udp://host:port}
 * @param startMs  when it started (platform time, ms since the epoch); the oldest agent is preferred
 *                 as container
 * @param services what it registered with the DF; empty if nothing
 */
public record AgentEntry(String name, String address, long startMs, List<ServiceDescription> services) {

    /**
     * The election order: the oldest start first; among equal starts the lowest port, then the name.
     * The first entry in this order is the preferred container.
     */
    public static final Comparator<AgentEntry> SENIORITY = Comparator.comparingLong(AgentEntry::startMs)
            .thenComparingInt(AgentEntry::port).thenComparing(AgentEntry::name);

    /** The order used after three elections that did not agree: the lowest port wins. */
    public static final Comparator<AgentEntry> BY_PORT = Comparator.comparingInt(AgentEntry::port)
            .thenComparing(AgentEntry::name);

    public AgentEntry {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(address, "address");
        services = services == null ? List.of() : List.copyOf(services);
    }

    /** The AID others send to: the name and the address. */
    public AID aid() {
        return new AID(name, address);
    }

    /** The parsed transport address; {@code null} if it is not one. */
    public Address transportAddress() {
        return Address.parse(address);
    }

    /** The port of its address, or 0. */
    public int port() {
        Address a = transportAddress();
        return a == null ? 0 : a.port();
    }

    public AgentEntry withServices(List<ServiceDescription> s) {
        return new AgentEntry(name, address, startMs, s);
    }
}
