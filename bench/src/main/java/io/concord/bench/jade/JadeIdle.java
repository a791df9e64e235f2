package io.concord.bench.jade;

/**
 * {@code <agents>}: a JADE 4.3 main container (no GUI, no MTP) with that many agents that do
 * nothing, each a plain {@code jade.core.Agent}. Prints {@code READY}; exits when its input closes.
 */
public final class JadeIdle {
    private JadeIdle() {
    }

    public static void main(String[] args) throws Exception {
        int n = Integer.parseInt(args[0]);
        JadePlatform p = new JadePlatform("idle", 0);
        for (int i = 0; i < n; i++) {
            p.start("i" + i, jade.core.Agent.class);
        }
        System.out.println("READY");
        System.out.flush();
        while (System.in.read() >= 0) {
            // until the parent closes our input
        }
        p.close();
        System.exit(0);
    }
}
