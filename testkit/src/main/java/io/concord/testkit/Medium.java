package io.concord.testkit;

import io.concord.core.net.Address;

/**
 * A man in the middle: decides what becomes of each datagram on a link (deliver it, late, twice,
 * changed, or not at all) and may insert datagrams of its own. The same medium drives the virtual
 * network ({@link VirtualNetwork#setMedium}) and the real-socket {@link UdpRelay}, so a threat is
 * written once and injected on both.
 */
@FunctionalInterface
public interface Medium {

    /** Where a medium puts what it lets through. */
    @FunctionalInterface
    interface Emitter {
        /** Delivers bytes to the datagram's destination after {@code delayNs}. */
        void deliver(long delayNs, byte[] bytes);
    }

    /**
     * One datagram on its way; call {@code out} zero or more times.
     *
     * @param datagram a copy the medium may keep and change
     */
    void carry(Address from, Address to, byte[] datagram, Emitter out);

    /** Lets everything through unchanged. */
    Medium PASS = (from, to, d, out) -> out.deliver(0, d);
}
