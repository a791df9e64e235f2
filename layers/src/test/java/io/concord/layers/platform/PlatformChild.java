package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.testkit.EchoAgent;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.PortRange;
import io.concord.layers.Profile;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

/**
 * One agent in a JVM of its own, for the multi-process tests: it prints its view of the platform
 * on every change ({@code STATE role=.. container=.. term=.. agents=..}) and every message it gets
 * ({@code GOT ..}); it answers REQUESTs with an INFORM; the parent writes {@code send <name> <text>}
 * on its standard input to make it send a REQUEST by name, {@code sniff <name>} to subscribe to an
 * agent's events, {@code deaf} to stop taking its mailbox.
 *
 * <p>Arguments: platform name, port range, agent name. The platform key comes from
 * {@code -Dconcord.home}.
 */
public final class PlatformChild {


    public static void main(String[] args) throws Exception {
        Platform.Builder b = Platform.builder().name(args[0]).ports(PortRange.parse(args[1])).profile(Profile.CLASS_7);
        if (args.length > 3) {
            b.host(args[3]);
        }
        // A small mailbox (-Dconcord.test.mailbox=N), for a receiver that falls behind soon.
        Integer mailbox = Integer.getInteger("concord.test.mailbox");
        io.concord.core.agent.AgentRuntime own = null;
        if (mailbox != null) {
            own = io.concord.core.agent.AgentRuntime.builder().platformName(args[0]).mailboxCapacity(mailbox).build();
            b.runtime(own);
        }
        Platform p = b.build();
        if (own != null) {
            own.start();
        }
        EchoAgent echo = new EchoAgent("echo:", m -> System.out.println("GOT " + m.getPerformative().wireName() + " from "
                + m.getSender().localName() + " " + m.getContent()));
        AID aid = p.startAgent(args[2], echo);
        p.runtime().execute(() -> {
            ContainerLayer c = Platform.containerLayer(p.runtime(), aid);
            java.util.function.Consumer<ContainerLayer> print = l -> System.out.println("STATE role=" + l.role()
                    + " container=" + l.containerName() + " term=" + l.term() + " agents=" + l.agents().size()
                    + " gal=" + l.globalAgents().size());
            c.addListener(print);
            print.accept(c); // the state before the listener was added

        });
        System.out.println("STARTED " + aid.name() + " " + aid.addresses().get(0));
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            String[] w = line.split(" ", 3);
            if (w.length == 3 && w[0].equals("send")) {
                AclMessage m = new AclMessage(Performative.REQUEST);
                m.addReceiver(AID.local(w[1], args[0]));
                m.setContent(w[2]);
                echo.send(m);
            } else if (w.length == 2 && w[0].equals("sniff")) {
                // The observation service's subscription, as the console's agent makes it: every event comes here.
                AclMessage m = new AclMessage(Performative.SUBSCRIBE);
                m.addReceiver(AID.local(w[1], args[0]));
                m.setOntology("concord-observe");
                m.setConversationId("sniff-" + w[1]);
                m.setContent("sniff");
                echo.send(m);
            } else if (w.length == 1 && w[0].equals("deaf")) {
                // Falls behind: takes nothing more from its mailbox, which fills; its window shuts.
                echo.stopTaking();
                System.out.println("DEAF");
            } else if (w.length == 2 && w[0].equals("register")) {
                p.runtime().execute(() -> Platform.of(echo).register(ServiceDescription.ofType(w[1]))
                        .whenComplete((ok, e) -> System.out.println(e == null ? "REGISTERED " + w[1] : "REGISTER-FAILED " + e)));
            } else if (w.length == 2 && w[0].equals("search")) {
                p.runtime().execute(() -> Platform.of(echo).searchAtDf(ServiceDescription.ofType(w[1]))
                        .whenComplete((found, e) -> System.out.println(e != null ? "SEARCH-FAILED " + e
                                : "FOUND " + w[1] + " " + found.stream().map(AgentEntry::name).sorted().toList())));
            }
        }
        p.close();
    }
}
