package io.concord.examples;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.layers.Platform;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.PlatformServices;

import java.util.List;

/**
 * Reads an agent named in a Boot argument: {@code seller1} is an agent of this platform,
 * {@code seller1@jadeplat=http://10.0.0.7:7778/acc} an agent of another platform (a JADE one)
 * reached at that address.
 */
final class Receivers {
    private Receivers() {
    }

    static AID parse(String arg, AID self) {
        String a = arg.trim();
        int eq = a.indexOf('=');
        if (eq > 0) {
            String name = a.substring(0, eq).trim();
            String url = a.substring(eq + 1).trim();
            if (!name.contains("@") || url.isEmpty()) {
                throw new IllegalArgumentException("'" + arg + "': an agent of another platform is written "
                        + "name@platform=http://host:port/acc");
            }
            return new AID(name, url);
        }
        if (a.isEmpty()) {
            throw new IllegalArgumentException("an empty agent name");
        }
        return a.contains("@") ? new AID(a) : AID.local(a, self.platform());
    }

    /** The agent's platform services (its DF, its agent list), or null if it runs on a bare runtime, not a {@code Platform}. */
    static PlatformServices platform(Agent self) {
        try {
            return Platform.of(self);
        } catch (IllegalStateException notOnAPlatform) {
            return null;
        }
    }

    /**
     * True once every agent of this platform among them is in the platform's agent list: a
     * message to a name not listed yet is dropped, so the examples wait for the others to start.
     * Agents of other platforms are not waited for (the bridge answers FAILURE if they are gone).
     */
    static boolean listed(Agent self, List<AID> aids) {
        List<AgentEntry> here = Platform.of(self).agents();
        for (AID a : aids) {
            if (a.platform().equalsIgnoreCase(self.getAID().platform())
                    && here.stream().noneMatch(e -> e.name().equalsIgnoreCase(a.name()))) {
                return false;
            }
        }
        return true;
    }
}
