package io.concord.bench.child;

import io.concord.bench.support.Chain;
import io.concord.bench.support.Platforms;
import io.concord.bench.support.Rounds;

import io.concord.bench.concord.ConcordChainLink;
import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.examples.BookSeller;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

/**
 * One Concord agent in its own JVM: {@code link <name> <platform>} or {@code seller <name> <price>
 * <platform>}. Prints {@code READY <its address>}; a link then takes {@code NEXT <name> <address>}.
 */
public final class ProcessAgent {
    private ProcessAgent() {
    }

    public static void main(String[] args) throws Exception {
        String kind = args[0];
        String name = args[1];
        String platform = args[args.length - 1];
        try (AgentRuntime rt = Platforms.concord(platform)) {
            Agent agent = kind.equals("link") ? new ConcordChainLink(new Rounds(), false, Chain.SECRET)
                    : new BookSeller(Integer.parseInt(args[2]));
            AID aid = rt.startAgent(name, agent);
            System.out.println("READY " + aid.addresses().get(0));
            System.out.flush();
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            String line;
            while ((line = in.readLine()) != null) {
                String[] p = line.split(" ");
                if (p[0].equals("NEXT") && agent instanceof ConcordChainLink link) {
                    link.next = new AID(p[1] + "@bench", p[2]);
                }
            }
        }
    }
}
