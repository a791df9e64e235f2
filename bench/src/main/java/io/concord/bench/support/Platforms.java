package io.concord.bench.support;

import io.concord.core.agent.AgentRuntime;
import io.concord.core.net.SocketNetwork;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;

/** The platforms a benchmark compares, and how to start Concord's. */
public final class Platforms {
    /** Concord with the full class-7 stack; Concord class 7 forced through the kernel; closed; JADE. */
    public static final String CONCORD_CLASS7 = "concord-class7";
    public static final String CONCORD_CLASS7_SOCKETS = "concord-class7-sockets";
    public static final String CONCORD_CLOSED = "concord-closed";
    public static final String JADE = "jade";

    public static final PlatformKey KEY = PlatformKey.ofHex("0f".repeat(32));

    private Platforms() {
    }

    /** A started Concord runtime for the named variant. */
    public static AgentRuntime concord(String platform) {
        return concord(platform, null);
    }

    /** As {@link #concord(String)}, one of the loops of {@code group} (null: a runtime alone). */
    public static AgentRuntime concord(String platform, io.concord.core.agent.LoopGroup group) {
        Profile profile = platform.equals(CONCORD_CLOSED) ? Profile.CLOSED : Profile.CLASS_7;
        AgentRuntime.Builder b = AgentRuntime.builder().platformName("bench")
                .stack(SafetyStack.builder().profile(profile).platformKey(KEY).identities(IdentityStore.ephemeral()).build())
                .group(group);
        if (platform.equals(CONCORD_CLASS7_SOCKETS)) {
            b.network(new SocketNetwork(1 << 20, false));
        }
        return b.build().start();
    }
}
