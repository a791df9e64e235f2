package io.concord.layers;

import io.concord.core.layer.Layer;
import io.concord.core.net.Address;
import io.concord.core.net.Transport;
import io.concord.layers.communication.CommunicationLayer;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;
import io.concord.layers.parser.Membership;
import io.concord.layers.parser.ParserLayer;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;
import io.concord.layers.security.SecurityLayer;
import io.concord.layers.sequence.SequenceLayer;
import io.concord.layers.temporal.PlatformClock;
import io.concord.layers.temporal.TemporalLayer;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.EnumSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.function.Supplier;

/**
 * Builds the EN 50159 stack every agent carries, top first: parser, sequence, temporal, security,
 * communication. Pick a {@link Profile}; change what you need; {@link Builder#build()} checks the
 * whole choice and fails at once, naming the problem, on a combination that cannot work.
 *
 * <pre>{@code
 * AgentRuntime rt = AgentRuntime.builder()
 *         .stack(SafetyStack.builder().profile(Profile.CLASS_7).build())
 *         .build();
 * }</pre>
 */
public final class SafetyStack {

    /** The layers, for {@link Builder#without}. */
    public enum LayerKind { PARSER, SEQUENCE, TEMPORAL, SECURITY, COMMUNICATION }

    private SafetyStack() {
    }

    public static Builder builder() {
        return new Builder();
    }

    /** The class-7 stack with the user's platform key and identities. */
    public static Supplier<List<Layer>> defaults() {
        return builder().build();
    }

    /** Settings; every one checked at {@link #build()}. */
    public static final class Builder {
        private Profile profile = Profile.CLASS_7;
        private PlatformKey platformKey;
        private IdentityStore identities;
        private Membership membership = Membership.open();
        private Transport transport = Transport.UDP;
        private Integer maxFrameBytes;
        private Integer copies;
        private long acceptanceWindowMs = 2_000;
        private long handshakeWindowMs = 30_000;
        private SequenceLayer.Config sequence = SequenceLayer.Config.defaults();
        private String timeSourceName;
        private Address timeSourceAddress;
        private long syncIntervalMs = 10_000;
        private final EnumSet<LayerKind> without = EnumSet.noneOf(LayerKind.class);
        private final EnumSet<Defence> off = EnumSet.noneOf(Defence.class);

        private Builder() {
        }

        public Builder profile(Profile p) {
            this.profile = Objects.requireNonNull(p, "profile");
            return this;
        }

        /** The platform key; by default the user's ({@code ~/.concord/platform.key}, created if absent). */
        public Builder platformKey(PlatformKey key) {
            this.platformKey = Objects.requireNonNull(key, "platformKey");
            return this;
        }

        /** Where agents' identities are kept; by default {@code ~/.concord/identities}. */
        public Builder identities(IdentityStore store) {
            this.identities = Objects.requireNonNull(store, "identities");
            return this;
        }

        public Builder membership(Membership m) {
            this.membership = Objects.requireNonNull(m, "membership");
            return this;
        }

        /** The transport agents with this stack run on: UDP (default) or TCP. */
        public Builder transport(Transport t) {
            this.transport = Objects.requireNonNull(t, "transport");
            return this;
        }

        /** The largest frame sent or accepted; 8 KiB by default on UDP, 16 KiB on TCP. */
        public Builder maxFrameBytes(int bytes) {
            this.maxFrameBytes = bytes;
            return this;
        }

        /** How many times each frame is sent; 2 by default on UDP, 1 (and only 1) on TCP. */
        public Builder copies(int n) {
            this.copies = n;
            return this;
        }

        /** How far a frame's stamp may lie from the platform time; 2 s by default. */
        public Builder acceptanceWindowMs(long ms) {
            this.acceptanceWindowMs = ms;
            return this;
        }

        public Builder handshakeWindowMs(long ms) {
            this.handshakeWindowMs = ms;
            return this;
        }

        public Builder sequence(SequenceLayer.Config config) {
            this.sequence = Objects.requireNonNull(config, "sequence");
            return this;
        }

        /** The agent whose clock is the platform's (the container), and how often to sync with it. */
        public Builder timeSource(String agentName, Address address, long syncIntervalMs) {
            this.timeSourceName = Objects.requireNonNull(agentName, "agentName");
            this.timeSourceAddress = Objects.requireNonNull(address, "address");
            this.syncIntervalMs = syncIntervalMs;
            return this;
        }

        /**
         * Switches defences off in the stacks this builder makes, and in no other: for the threat
         * tests alone, which show each threat reaching an agent without its defence. Never in a
         * real platform.
         */
        public Builder withoutDefences(Defence... defences) {
            off.addAll(Arrays.asList(defences));
            return this;
        }

        /** As {@link #withoutDefences(Defence...)}. */
        public Builder withoutDefences(Collection<Defence> defences) {
            off.addAll(defences);
            return this;
        }

        /** Leaves layers out (the profile must allow it). */
        public Builder without(LayerKind... kinds) {
            without.addAll(List.of(kinds));
            return this;
        }

        /**
         * Checks the settings and returns the factory of stacks (one new stack per agent).
         *
         * @throws IllegalArgumentException naming what cannot work, and what to do
         */
        public Supplier<List<Layer>> build() {
            for (LayerKind needed : List.of(LayerKind.PARSER, LayerKind.SECURITY, LayerKind.COMMUNICATION)) {
                if (without.contains(needed)) {
                    throw new IllegalArgumentException("a stack cannot work without its " + needed + " layer: the parser "
                            + "turns messages into bytes, the security layer frames them, the communication layer "
                            + "sends them");
                }
            }
            if (profile != Profile.CLOSED && (without.contains(LayerKind.SEQUENCE) || without.contains(LayerKind.TEMPORAL))) {
                throw new IllegalArgumentException(profile + " needs sequence numbers and timestamps against repetition, "
                        + "deletion, resequencing and delay; leave them in, or use Profile.CLOSED on a closed network");
            }
            if (timeSourceName != null && without.contains(LayerKind.TEMPORAL)) {
                throw new IllegalArgumentException("a time source needs the temporal layer");
            }
            if (timeSourceName != null && syncIntervalMs <= 0) {
                throw new IllegalArgumentException("syncIntervalMs must be > 0, got " + syncIntervalMs);
            }
            if (handshakeWindowMs <= 0) {
                throw new IllegalArgumentException("handshakeWindowMs must be > 0, got " + handshakeWindowMs);
            }
            int frameLimit = maxFrameBytes != null ? maxFrameBytes
                    : transport == Transport.UDP ? CommunicationLayer.DEFAULT_MAX_UDP_BYTES : CommunicationLayer.DEFAULT_MAX_TCP_BYTES;
            int copiesSent = copies != null ? copies : transport == Transport.UDP ? 2 : 1;
            CommunicationLayer.Config comm = new CommunicationLayer.Config(transport, frameLimit, copiesSent);
            TemporalLayer.Config temporal = timeSourceName == null ? TemporalLayer.Config.window(acceptanceWindowMs)
                    : new TemporalLayer.Config(acceptanceWindowMs, Frames.id(timeSourceName), timeSourceAddress, syncIntervalMs);
            PlatformKey key = profile == Profile.CLOSED ? null
                    : platformKey != null ? platformKey : PlatformKey.userDefault();
            IdentityStore ids = profile != Profile.CLASS_7 ? null
                    : identities != null ? identities : IdentityStore.directory(PlatformKey.defaultDirectory().resolve("identities"));
            SecurityLayer.Config security = new SecurityLayer.Config(profile.protection(), key, ids, handshakeWindowMs, 1024);
            Membership members = membership;
            SequenceLayer.Config seq = sequence;
            EnumSet<LayerKind> out = EnumSet.copyOf(without);
            int overhead = Frames.HEADER_BYTES + Frames.CRC_BYTES
                    + (profile == Profile.CLOSED ? 0 : Frames.TAG_BYTES)
                    + (out.contains(LayerKind.SEQUENCE) ? 0 : SequenceLayer.HEADER_BYTES)
                    + (out.contains(LayerKind.TEMPORAL) ? 0 : TemporalLayer.HEADER_BYTES);
            int limit = frameLimit;
            Set<Defence> offHere = Set.copyOf(off);
            return () -> {
                PlatformClock clock = new PlatformClock();
                List<Layer> layers = new ArrayList<>(5);
                layers.add(new ParserLayer(members, out.contains(LayerKind.TEMPORAL) ? null : clock,
                        !offHere.contains(Defence.IDENTIFICATION), limit, overhead));
                if (!out.contains(LayerKind.SEQUENCE)) {
                    layers.add(new SequenceLayer(seq, offHere, profile == Profile.CLOSED && copiesSent > 1));
                }
                if (!out.contains(LayerKind.TEMPORAL)) {
                    layers.add(new TemporalLayer(temporal, clock, offHere));
                }
                layers.add(new SecurityLayer(security, offHere));
                layers.add(new CommunicationLayer(comm));
                return layers;
            };
        }
    }
}
