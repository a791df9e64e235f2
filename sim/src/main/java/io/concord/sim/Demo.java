package io.concord.sim;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.proto.ContractNetResponder;
import io.concord.core.proto.Conversations;
import io.concord.core.proto.FailureException;
import io.concord.core.proto.FipaProtocols;
import io.concord.core.proto.RefuseException;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.PlatformKey;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The platform demo: agents in one JVM, each with its own UDP port on loopback and the class-7
 * safety stack, served by one loop. A buyer runs a contract net with three book sellers and buys
 * from the cheapest; then five agents pass a secret round a ring. Everything said is printed.
 */
public final class Demo {
    private static final PrintStream OUT = System.out;

    private Demo() {
    }

    public static void main(String[] args) throws Exception {
        try (AgentRuntime runtime = AgentRuntime.builder().platformName("demo")
                .stack(SafetyStack.builder().profile(Profile.CLASS_7).build()).build().start()) {
            OUT.println("Concord demo: one runtime, one loop, every agent on its own UDP port on 127.0.0.1");
            OUT.println("Every agent carries the EN 50159 class-7 stack: sequence numbers, timestamps, CRC-32C, and");
            OUT.println("AES-GCM with per-pair keys from signed X25519 handshakes; platform key: "
                    + PlatformKey.defaultDirectory().resolve("platform.key"));
            List<AID> sellers = new ArrayList<>();
            int[][] stock = {{42, 3}, {35, 0}, {39, 5}};
            for (int i = 0; i < stock.length; i++) {
                AID aid = runtime.startAgent("seller" + (i + 1), new Seller(stock[i][0], stock[i][1]));
                sellers.add(aid);
                OUT.printf("  started %-16s at %s  (price %d, %d in stock)%n", aid.name(), aid.addresses().get(0),
                        stock[i][0], stock[i][1]);
            }
            CompletableFuture<String> bought = new CompletableFuture<>();
            runtime.startAgent("buyer", new Buyer(sellers, "The Art of Agents", bought));
            OUT.println("  result: " + bought.get(10, TimeUnit.SECONDS));

            OUT.println();
            OUT.println("Chain: 5 agents pass a 500-byte secret round a ring, 3 rounds");
            CountDownLatch rounds = new CountDownLatch(3);
            int n = 5;
            List<ChainLink> links = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                links.add(new ChainLink(i == 0 ? rounds : null));
            }
            List<AID> ring = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                ring.add(runtime.startAgent("link" + i, links.get(i)));
            }
            for (int i = 0; i < n; i++) {
                links.get(i).next = ring.get((i + 1) % n);
            }
            runtime.execute(links.get(0)::startRound);
            if (!rounds.await(10, TimeUnit.SECONDS)) {
                OUT.println("  the ring did not complete 3 rounds in 10 s");
            }
            OUT.println();
            OUT.println("Dropped frames by reason (copies sent against loss are expected here): " + runtime.drops());
        }
    }

    /** Sells one title at a fixed price while it has stock; answers contract-net CFPs. */
    static final class Seller extends Agent {
        private final int price;
        private int stock;

        Seller(int price, int stock) {
            this.price = price;
            this.stock = stock;
        }

        @Override
        protected void setup() {
            addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET)) {
                @Override
                protected AclMessage handleCfp(AclMessage cfp) throws RefuseException {
                    if (stock == 0) {
                        OUT.printf("  %s: REFUSE  %s (out of stock)%n", getLocalName(), cfp.getContent());
                        throw new RefuseException("(out-of-stock \"" + cfp.getContent() + "\")");
                    }
                    AclMessage propose = cfp.createReply();
                    propose.setPerformative(Performative.PROPOSE);
                    propose.setContent(Integer.toString(price));
                    OUT.printf("  %s: PROPOSE %d%n", getLocalName(), price);
                    return propose;
                }

                @Override
                protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept)
                        throws FailureException {
                    if (stock == 0) {
                        throw new FailureException("(sold-out)");
                    }
                    stock--;
                    AclMessage inform = accept.createReply();
                    inform.setPerformative(Performative.INFORM);
                    inform.setContent("(sold \"" + cfp.getContent() + "\" " + price + ")");
                    OUT.printf("  %s: INFORM  sold at %d, %d left%n", getLocalName(), price, stock);
                    return inform;
                }

                @Override
                protected void handleRejectProposal(AclMessage cfp, AclMessage propose, AclMessage reject) {
                    OUT.printf("  %s: was rejected%n", getLocalName());
                }
            });
        }
    }

    /** Asks every seller for the title and buys from the cheapest. */
    static final class Buyer extends Agent {
        private final List<AID> sellers;
        private final String title;
        private final CompletableFuture<String> result;

        Buyer(List<AID> sellers, String title, CompletableFuture<String> result) {
            this.sellers = sellers;
            this.title = title;
            this.result = result;
        }

        @Override
        protected void setup() {
            addBehaviour(new OneShotBehaviour(this) {
                @Override
                public void action() {
                    AclMessage cfp = new AclMessage(Performative.CFP);
                    sellers.forEach(cfp::addReceiver);
                    cfp.setContent(title);
                    cfp.setReplyByEpochMs(currentTimeMillis() + 2_000);
                    OUT.printf("  %s: CFP     \"%s\" to %d sellers%n", getLocalName(), title, sellers.size());
                    Conversations.contractNet(Buyer.this, cfp,
                                    proposals -> proposals.stream()
                                            .min(Comparator.comparingInt(p -> Integer.parseInt(p.getContent())))
                                            .orElse(null))
                            .whenComplete((outcome, error) -> result.complete(error != null
                                    ? "no purchase: " + error.getMessage()
                                    : "bought from " + outcome.proposal().getSender().localName() + ": "
                                    + outcome.result().getContent()));
                }
            });
        }
    }

    /** One link of the ring: passes the secret on; the first link checks it came back unchanged. */
    static final class ChainLink extends Agent {
        private final CountDownLatch rounds;
        AID next;
        private String secret;
        private long startNs;

        ChainLink(CountDownLatch rounds) {
            this.rounds = rounds;
        }

        void startRound() {
            secret = "s".repeat(500 - 8) + String.format("%08d", rounds.getCount());
            startNs = runtime().clock().nanoTime();
            pass(secret);
        }

        private void pass(String content) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(next);
            m.setContent(content);
            send(m);
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m = receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    if (rounds == null) {
                        pass(m.getContent());
                        return;
                    }
                    long us = (runtime().clock().nanoTime() - startNs) / 1_000;
                    OUT.printf("  %s: the secret came back %s after %d hops in %d us%n", getLocalName(),
                            m.getContent().equals(secret) ? "unchanged" : "CHANGED", 5, us);
                    rounds.countDown();
                    if (rounds.getCount() > 0) {
                        startRound();
                    }
                }
            });
        }
    }
}
