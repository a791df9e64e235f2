package io.concord.examples;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.layers.Platform;
import io.concord.layers.PlatformServices;
import io.concord.layers.platform.ServiceDescription;

import java.util.SplittableRandom;

/**
 * The book seller of the dissertation's annex D, as JADE's runs it: answers a QUERY-REF with an
 * INFORM holding its price, and a REQUEST (an order, its content the quantity) with AGREE, or
 * REFUSE if it orders less than one. It registers a {@code book-selling} service with the DF, so
 * buyers on Concord, and JADE agents through the DF mirror, find it.
 *
 * <p>Boot arguments: {@code BookSeller(price)}, or none for a random price from 0 to 99 for every
 * query, as the annex's seller does. Prints what it says. A program (the benchmarks, the tests)
 * gives the price to {@link #BookSeller(int)} instead, and the seller says nothing; on a runtime
 * that is not a {@code Platform} (the benchmarks'), it answers all the same, in no DF.
 */
public class BookSeller extends Agent {
    private Integer fixed;
    private SplittableRandom random;
    private final boolean prints;

    /** The seller Boot starts: its price from the arguments; prints what it says. */
    public BookSeller() {
        this.prints = true;
    }

    /** A seller at a fixed price that prints nothing, for a program. */
    public BookSeller(int price) {
        this.fixed = price;
        this.prints = false;
    }

    @Override
    protected void setup() {
        Object[] a = getArguments();
        if (fixed == null && a.length > 0 && !a[0].toString().isBlank()) {
            try {
                fixed = Integer.parseInt(a[0].toString().trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("BookSeller(price): the price is a whole number, got '" + a[0] + "'");
            }
        } else if (fixed == null) {
            random = new SplittableRandom();
        }
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                PlatformServices platform = Receivers.platform(myAgent);
                if (platform == null) {
                    return; // a bare runtime: no DF to be found in
                }
                platform.register(ServiceDescription.of("book-selling", getLocalName()))
                        .whenComplete((ok, e) -> say(getLocalName() + ": " + (e == null
                                ? "selling; registered book-selling with the DF"
                                : "could not register with the DF: " + e.getMessage())));
            }
        });
        addBehaviour(Inbox.each(this, MessageTemplate.matchAll(), this::answer));
    }

    private void answer(AclMessage m) {
        AclMessage reply = m.createReply();
        switch (m.getPerformative()) {
            case QUERY_REF -> {
                int price = fixed != null ? fixed : random.nextInt(100);
                reply.setPerformative(Performative.INFORM);
                reply.setContent(Integer.toString(price));
                if (prints) {
                    say(getLocalName() + ": QUERY-REF from " + m.getSender().name() + ", answers $" + price);
                }
            }
            case REQUEST -> {
                int quantity;
                try {
                    quantity = Integer.parseInt(m.getContent() == null ? "" : m.getContent().trim());
                } catch (NumberFormatException e) {
                    quantity = 0;
                }
                reply.setPerformative(quantity >= 1 ? Performative.AGREE : Performative.REFUSE);
                if (prints) {
                    say(getLocalName() + ": order of " + m.getContent() + " from " + m.getSender().name()
                            + ", " + reply.getPerformative().wireName());
                }
            }
            case FAILURE, NOT_UNDERSTOOD, AGREE, REFUSE, INFORM -> {
                return; // answers to nothing it asked: never answered, or two agents would answer each other forever
            }
            default -> {
                reply.setPerformative(Performative.NOT_UNDERSTOOD);
                reply.setContent("(a book seller answers QUERY-REF and REQUEST)");
            }
        }
        send(reply);
    }

    private void say(String line) {
        if (prints) {
            System.out.println(line);
        }
    }
}
