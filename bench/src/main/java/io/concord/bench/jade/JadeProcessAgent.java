package io.concord.bench.jade;

import io.concord.bench.support.Rounds;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.wrapper.ContainerController;

/**
 * One JADE agent in its own JVM, in a peripheral container joined to the main container at the
 * given port: {@code <mainPort> link <name> <index> <n>} or {@code <mainPort> seller <name> <price>}.
 * Prints READY once the agent is set up; exits when its input closes.
 */
public final class JadeProcessAgent {
    private JadeProcessAgent() {
    }

    public static void main(String[] args) throws Exception {
        Runtime rt = Runtime.instance();
        rt.setCloseVM(false);
        Profile p = new ProfileImpl();
        p.setParameter(Profile.MAIN_HOST, "127.0.0.1");
        p.setParameter(Profile.MAIN_PORT, args[0]);
        p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(Profile.CONTAINER_NAME, "c-" + args[2]);
        ContainerController c = rt.createAgentContainer(p);
        if (c == null) {
            throw new IllegalStateException("the peripheral container could not join the main container");
        }
        Rounds ready = new Rounds();
        ready.expectReady(1);
        if (args[1].equals("link")) {
            c.createNewAgent(args[2], JadeChainLink.class.getName(), new Object[]{ready, Integer.parseInt(args[3]),
                    Integer.parseInt(args[4]), JadeChainLink.class.getSimpleName()}).start();
        } else {
            c.createNewAgent(args[2], JadeBooks.Seller.class.getName(), new Object[]{Integer.parseInt(args[3]), ready}).start();
        }
        ready.awaitReady();
        System.out.println("READY");
        System.out.flush();
        while (System.in.read() >= 0) {
            // until the parent closes our input
        }
        System.exit(0);
    }
}
