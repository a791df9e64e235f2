package io.concord.bench.child;

import io.concord.bench.concord.ConcordHttpEcho;
import io.concord.bench.jade.JadeHttpEcho;
import io.concord.bench.jade.JadePlatform;
import io.concord.bench.support.Platforms;
import io.concord.core.agent.PortRange;
import io.concord.jade.HttpMtp;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.IdentityStore;

/**
 * The other platform of the HTTP benchmark, in a JVM of its own (a JVM holds one JADE platform):
 * an echo agent on JADE or on Concord, reachable at {@code http://127.0.0.1:<port>/acc}.
 * Arguments: jade|concord|floor (see {@link HttpFloor}), the HTTP port. Prints {@code READY echo@httptarget} and runs until its
 * standard input closes.
 */
public final class HttpTarget {
    private HttpTarget() {
    }

    public static void main(String[] args) throws Exception {
        int port = Integer.parseInt(args[1]);
        AutoCloseable platform;
        if (args[0].equals("floor")) {
            HttpFloor f = new HttpFloor(port);
            platform = f::close;
        } else if (args[0].equals("jade")) {
            JadePlatform j = new JadePlatform("httptarget", port);
            j.start("echo", JadeHttpEcho.class);
            platform = j;
        } else {
            Platform p = Platform.builder().name("httptarget").ports(PortRange.of(7951, 7990)).network(null)
                    .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(Platforms.KEY)
                            .identities(IdentityStore.ephemeral()).build())
                    .gateway(() -> new HttpMtp("127.0.0.1", port)).build();
            p.startAgent("echo", new ConcordHttpEcho());
            platform = p;
        }
        System.out.println("READY echo@httptarget");
        while (System.in.read() >= 0) {
            // until the parent closes our input
        }
        platform.close();
        System.exit(0);
    }
}
