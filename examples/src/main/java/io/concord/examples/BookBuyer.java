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
import java.util.function.BooleanSupplier;

/**
 * The book buyer of the dissertation's annex C, as JADE's runs it: sends a QUERY-REF to every
 * seller, takes the quotes (INFORM) that come within a second, and orders one book (REQUEST, content
 * {@code 1}) from the cheapest if its price is at most 80; the seller's AGREE ends the purchase. No
 * quote, a price too high, a REFUSE or no answer within a second: it starts again.
 *
 * <p>Boot arguments: the sellers, each {@code name} (on this platform) or
 * {@code name@platform=http://host:port/acc} (a JADE agent, through the bridge), and the options
 * {@code rounds=N} (purchases to make, 1 by default), {@code max=P} (80) and {@code sellers=N}
 * (with no seller named, how many the DF must list before the first question; 1). With no seller
 * named, it buys from the agents the DF lists as {@code book-selling}. Prints each step and, at the
 * end, {@code bought N books ... mean X ms a purchase}.
 *
 * <p>A program (the benchmarks) names the sellers to {@link #BookBuyer(List, BooleanSupplier)}
 * instead: that buyer says nothing, buys once {@link #buy()} is called, and buys again after each
 * purchase for as long as the program says so.
 */
public class BookBuyer extends Agent {
    private static final long WAIT_MS = 1_000;
    private final List<AID> sellers = new ArrayList<>();
    private final boolean prints;
    /** After a purchase, whether to buy another at once; null for Boot's buyer, which buys {@code rounds}. */
    private final BooleanSupplier another;
    private boolean fromDf;
    private int dfSellers = 1;
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

    /** The buyer Boot starts: sellers and options from the arguments; prints each step. */
    public BookBuyer() {
        this.prints = true;
        this.another = null;
    }

    /**
     * A buyer for a program: it asks these sellers (running, and reachable at their addresses),
     * prints nothing, makes a purchase when {@link #buy()} is called and, after each, another at
     * once while {@code another} returns true (on the agent's loop).
     */
    public BookBuyer(List<AID> sellers, BooleanSupplier another) {
        if (sellers.isEmpty()) {
            throw new IllegalArgumentException("a program's buyer needs the sellers it asks");
        }
        this.sellers.addAll(sellers);
        this.prints = false;
        this.another = another;
        this.rounds = 0;
    }

    /** Starts a purchase now (after the one under way, if any). Call on the agent's loop. */
    public void buy() {
        rounds++;
        loop.restart();
    }

    @Override
    protected void setup() {
        for (Object o : getArguments()) {
            String a = o.toString().trim();
            if (a.startsWith("rounds=")) {
                rounds = Integer.parseInt(a.substring(7).trim());
            } else if (a.startsWith("max=")) {
                maxPrice = Integer.parseInt(a.substring(4).trim());
            } else if (a.startsWith("sellers=")) {
                dfSellers = Integer.parseInt(a.substring(8).trim());
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
                    if (prints) {
                        say(getLocalName() + ": quote $" + price + " from " + m.getSender().name());
                    }
                    if (best == null || price < best) {
                        best = price;
                        bestSeller = m.getSender();
                    }
                } catch (RuntimeException e) {
                    say(getLocalName() + ": a quote that is not a price from " + m.getSender().name());
                }
            } else if (m.getPerformative() == Performative.FAILURE) {
                say(getLocalName() + ": " + m.getSender().name() + " says FAILURE: " + m.getContent());
            }
            if (answers >= sellers.size()) {
                order();
            }
        } else if (m.getPerformative() == Performative.AGREE && m.getSender().equals(bestSeller)) {
            long took = currentTimeMillis() - startedMs;
            bought++;
            totalMs += took;
            if (prints) {
                say(getLocalName() + ": AGREE from " + m.getSender().name() + ": bought at $" + best + " in "
                        + took + " ms (" + bought + " of " + rounds + ")");
            }
            conversation = null;
            deadlineMs = 0;
            if (another != null && bought == rounds && another.getAsBoolean()) {
                rounds++;
            }
            if (bought == rounds && prints) {
                say(getLocalName() + ": bought " + bought + (bought == 1 ? " book" : " books") + " in " + attempt
                        + (attempt == 1 ? " attempt" : " attempts") + ", mean "
                        + (totalMs / bought) + " ms a purchase");
            }
        } else if (m.getPerformative() == Performative.REFUSE || m.getPerformative() == Performative.FAILURE) {
            say(getLocalName() + ": " + m.getPerformative().wireName() + " from " + m.getSender().name()
                    + "; starting again");
            again();
        }
    }

    /**
     * With no seller named, the DF's book sellers; false while it lists fewer than
     * {@code sellers=N}, or while a seller named on this platform has not started. A program's
     * sellers are there.
     */
    private boolean findSellers() {
        if (another != null) {
            return true;
        }
        if (!fromDf) {
            return Receivers.listed(this, sellers);
        }
        sellers.clear();
        for (AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.ofType("book-selling"))) {
            sellers.add(e.aid());
        }
        return sellers.size() >= dfSellers;
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
        if (prints) {
            say(getLocalName() + ": asking " + sellers.size() + (sellers.size() == 1 ? " seller" : " sellers")
                    + " for a price");
        }
        send(q);
    }

    private void order() {
        if (best == null || best > maxPrice) {
            say(getLocalName() + ": " + (best == null ? "no quotes" : "best price $" + best + " is above $"
                    + maxPrice) + "; starting again");
            again();
            return;
        }
        ordered = true;
        deadlineMs = currentTimeMillis() + WAIT_MS;
        if (prints) {
            say(getLocalName() + ": best price $" + best + " from " + bestSeller.name() + ", ordering 1");
        }
        AclMessage r = new AclMessage(Performative.REQUEST).addReceiver(bestSeller);
        r.setConversationId(conversation);
        r.setContent("1");
        send(r);
    }

    private void timedOut() {
        if (!ordered) {
            order();
        } else {
            say(getLocalName() + ": " + bestSeller.name() + " did not answer the order; starting again");
            again();
        }
    }

    /** Starts a new attempt half a second from now. */
    private void again() {
        conversation = null;
        deadlineMs = currentTimeMillis() + 500;
    }

    private void say(String line) {
        if (prints) {
            System.out.println(line);
        }
    }
}
