package io.concord.examples;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.layers.Platform;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.List;

/**
 * The book buyer of the dissertation's annex C, as JADE's runs it: sends a QUERY-REF to every
 * seller, takes the quotes (INFORM) that come within a second, and orders one book (REQUEST, content
 * {@code 1}) from the cheapest if its price is at most 80; the seller's AGREE ends the purchase. No
 * quote, a price too high, a REFUSE or no answer within a second: it starts again.
 *
 * <p>Boot arguments: the sellers, each {@code name} (on this platform) or
 * {@code name@platform=http://host:port/acc} (a JADE agent, through the bridge), and the options
 * {@code rounds=N} (purchases to make, 1 by default) and {@code max=P} (80). With no seller named,
 * it buys from the agents the DF lists as {@code book-selling}. Prints each step and, at the end,
 * {@code bought N books ... mean X ms a purchase}.
 */
public class BookBuyer extends Agent {
    private static final long WAIT_MS = 1_000;
    private final List<AID> sellers = new ArrayList<>();
    private boolean fromDf;
    private int rounds = 1;
    private int maxPrice = 80;
    private int bought;
    private int attempt;
    private long totalMs;
    // the current attempt
    private String conversation;
    private long startedMs;
    private long deadlineMs;
    private int answers;
    private Integer best;
    private AID bestSeller;
    private boolean ordered;
    private CyclicBehaviour loop;

    @Override
    protected void setup() {
        for (Object o : getArguments()) {
            String a = o.toString().trim();
            if (a.startsWith("rounds=")) {
                rounds = Integer.parseInt(a.substring(7).trim());
            } else if (a.startsWith("max=")) {
                maxPrice = Integer.parseInt(a.substring(4).trim());
            } else if (!a.isEmpty()) {
                sellers.add(Receivers.parse(a, getAID()));
            }
        }
        fromDf = sellers.isEmpty();
        loop = new CyclicBehaviour(this) {
            @Override
            public void action() {
                step();
            }
        };
        addBehaviour(loop);
    }

    private void step() {
        long now = currentTimeMillis();
        if (conversation == null) {
            if (bought >= rounds) {
                loop.block();
                return;
            }
            if (now < deadlineMs || !findSellers()) {
                loop.block(Math.max(1, deadlineMs > now ? deadlineMs - now : 200));
                return;
            }
            ask();
            return;
        }
        AclMessage m = receive(MessageTemplate.matchConversationId(conversation));
        if (m == null) {
            if (now >= deadlineMs) {
                timedOut();
            } else {
                loop.block(deadlineMs - now);
            }
            return;
        }
        if (!ordered) {
            answers++;
            if (m.getPerformative() == Performative.INFORM) {
                try {
                    int price = Integer.parseInt(m.getContent().trim());
                    System.out.println(getLocalName() + ": quote $" + price + " from " + m.getSender().name());
                    if (best == null || price < best) {
                        best = price;
                        bestSeller = m.getSender();
                    }
                } catch (RuntimeException e) {
                    System.out.println(getLocalName() + ": a quote that is not a price from " + m.getSender().name());
                }
            } else if (m.getPerformative() == Performative.FAILURE) {
                System.out.println(getLocalName() + ": " + m.getSender().name() + " says FAILURE: " + m.getContent());
            }
            if (answers >= sellers.size()) {
                order();
            }
        } else if (m.getPerformative() == Performative.AGREE && m.getSender().equals(bestSeller)) {
            long took = currentTimeMillis() - startedMs;
            bought++;
            totalMs += took;
            System.out.println(getLocalName() + ": AGREE from " + m.getSender().name() + ": bought at $" + best + " in "
                    + took + " ms (" + bought + " of " + rounds + ")");
            conversation = null;
            deadlineMs = 0;
            if (bought == rounds) {
                System.out.println(getLocalName() + ": bought " + bought + " books in " + attempt + " attempts, mean "
                        + (totalMs / bought) + " ms a purchase");
            }
        } else if (m.getPerformative() == Performative.REFUSE || m.getPerformative() == Performative.FAILURE) {
            System.out.println(getLocalName() + ": " + m.getPerformative().wireName() + " from " + m.getSender().name()
                    + "; starting again");
            again();
        }
    }

    /**
     * With no seller named, the DF's book sellers; false while it lists none, or while a seller
     * named on this platform has not started.
     */
    private boolean findSellers() {
        if (!fromDf) {
            return Receivers.listed(this, sellers);
        }
        sellers.clear();
        for (AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.ofType("book-selling"))) {
            sellers.add(e.aid());
        }
        return !sellers.isEmpty();
    }

    private void ask() {
        attempt++;
        conversation = "books-" + getLocalName() + "-" + attempt;
        startedMs = currentTimeMillis();
        deadlineMs = startedMs + WAIT_MS;
        answers = 0;
        best = null;
        bestSeller = null;
        ordered = false;
        AclMessage q = new AclMessage(Performative.QUERY_REF);
        sellers.forEach(q::addReceiver);
        q.setConversationId(conversation);
        q.setReplyWith(conversation + "-q");
        q.setContent("(price (book \"The Art of Agents\"))");
        System.out.println(getLocalName() + ": asking " + sellers.size() + (sellers.size() == 1 ? " seller" : " sellers")
                + " for a price");
        send(q);
    }

    private void order() {
        if (best == null || best > maxPrice) {
            System.out.println(getLocalName() + ": " + (best == null ? "no quotes" : "best price $" + best + " is above $"
                    + maxPrice) + "; starting again");
            again();
            return;
        }
        ordered = true;
        deadlineMs = currentTimeMillis() + WAIT_MS;
        System.out.println(getLocalName() + ": best price $" + best + " from " + bestSeller.name() + ", ordering 1");
        AclMessage r = new AclMessage(Performative.REQUEST).addReceiver(bestSeller);
        r.setConversationId(conversation);
        r.setContent("1");
        send(r);
    }

    private void timedOut() {
        if (!ordered) {
            order();
        } else {
            System.out.println(getLocalName() + ": " + bestSeller.name() + " did not answer the order; starting again");
            again();
        }
    }

    /** Starts a new attempt half a second from now. */
    private void again() {
        conversation = null;
        deadlineMs = currentTimeMillis() + 500;
    }
}
