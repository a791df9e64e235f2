package io.concord.core.net;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.proto.AchieveREResponder;
import io.concord.core.proto.ContractNetResponder;
import io.concord.core.proto.Conversations;
import io.concord.core.proto.FipaProtocols;
import io.concord.core.proto.RefuseException;
import io.concord.core.proto.SubscriptionResponder;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;

/**
 * The far side of {@link TwoProcessUdpTest}: a JVM whose agents answer every protocol. Prints
 * {@code READY name uri} per agent, then serves until its standard input closes.
 */
public final class RemoteResponders {
    private RemoteResponders() {
    }

    public static void main(String[] args) throws Exception {
        try (AgentRuntime rt = AgentRuntime.builder().platformName("remote").build().start()) {
            print(rt.startAgent("echo", new LambdaAgent(a -> Conversations.serve(a,
                    AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST), req -> {
                        if ("refuse me".equals(req.getContent())) {
                            throw new RefuseException("(as-you-wish)");
                        }
                        return req.createReply().setPerformative(Performative.INFORM).setContent("echo " + req.getContent());
                    }))));
            print(rt.startAgent("oracle", new LambdaAgent(a -> Conversations.serve(a,
                    AchieveREResponder.createMessageTemplate(FipaProtocols.QUERY),
                    q -> q.createReply().setPerformative(Performative.INFORM).setContent("(= (answer) 42)")))));
            for (int price : new int[]{17, 12}) {
                print(rt.startAgent("seller" + price, new LambdaAgent(a -> Conversations.offer(a,
                        ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET),
                        cfp -> cfp.createReply().setPerformative(Performative.PROPOSE).setContent(Integer.toString(price)),
                        (cfp, p, acc) -> acc.createReply().setPerformative(Performative.INFORM).setContent("sold at " + price)))));
            }
            print(rt.startAgent("door", new LambdaAgent(RemoteResponders::door)));
            System.out.println("ALL READY");
            System.out.flush();
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            while (in.readLine() != null) {
                // serve until the parent closes our input
            }
        }
    }

    /** Accepts subscriptions and notifies three door positions at once. */
    private static void door(Agent a) {
        a.addBehaviour(new SubscriptionResponder(a, SubscriptionResponder.createMessageTemplate()) {
            @Override
            protected AclMessage handleSubscription(AclMessage subscribe) {
                AclMessage agree = subscribe.createReply();
                agree.setPerformative(Performative.AGREE);
                a.addBehaviour(new io.concord.core.agent.OneShotBehaviour() {
                    @Override
                    public void action() {
                        for (Subscription s : getSubscriptions()) {
                            for (String pos : new String[]{"opening", "open", "closing"}) {
                                s.notify(new AclMessage(Performative.INFORM).setContent(pos));
                            }
                        }
                    }
                });
                return agree;
            }
        });
    }

    private static void print(AID aid) {
        System.out.println("READY " + aid.localName() + " " + aid.addresses().get(0));
        System.out.flush();
    }
}
