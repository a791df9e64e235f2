package io.concord.sim.books;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.TickerBehaviour;
import io.concord.core.proto.Conversations;
import io.concord.layers.Platform;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ServiceDescription;

import java.util.Comparator;
import java.util.List;

/**
 * Buys one title: looks for its sellers in the yellow pages every 250 ms until it finds the
 * number it expects (or, after 10 s, any), asks them all with a contract net and buys from the
 * cheapest. Arguments: title, sellers to wait for (default 1). Prints what it says, then
 * {@code buyer: DONE}.
 */
public class BookBuyer extends Agent {
    private String title;
    private int expected;

    @Override
    protected void setup() {
        Object[] a = getArguments();
        if (a.length < 1) {
            throw new IllegalArgumentException("BookBuyer needs (title[, sellers to wait for])");
        }
        title = a[0].toString();
        expected = a.length > 1 ? Integer.parseInt(a[1].toString()) : 1;
        addBehaviour(new TickerBehaviour(this, 250) {
            private int ticks;

            @Override
            protected void onTick() {
                ticks++;
                List<AgentEntry> sellers = Platform.of(myAgent).searchCopy(ServiceDescription.of("book-selling", title));
                if (sellers.size() < expected && (ticks < 40 || sellers.isEmpty())) {
                    return;
                }
                stop();
                System.out.println(getLocalName() + ": the DF lists " + sellers.size() + " sellers of \"" + title + "\": "
                        + sellers.stream().map(e -> e.aid().localName() + "@" + e.address()).toList());
                AclMessage cfp = new AclMessage(Performative.CFP);
                sellers.forEach(s -> cfp.addReceiver(AID.local(s.aid().localName(), s.aid().platform())));
                cfp.setContent(title);
                cfp.setReplyByEpochMs(currentTimeMillis() + 3_000);
                System.out.println(getLocalName() + ": CFP \"" + title + "\" to " + sellers.size() + " sellers, by name");
                Conversations.contractNet(myAgent, cfp, proposals -> proposals.stream()
                                .min(Comparator.comparingInt(p -> Integer.parseInt(p.getContent()))).orElse(null))
                        .whenComplete((outcome, e) -> {
                            System.out.println(getLocalName() + ": " + (e != null ? "no purchase: " + e.getMessage()
                                    : "bought from " + outcome.proposal().getSender().localName() + ": "
                                    + outcome.result().getContent()));
                            System.out.println(getLocalName() + ": DONE");
                        });
            }
        });
    }
}
