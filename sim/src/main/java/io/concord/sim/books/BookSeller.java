package io.concord.sim.books;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.proto.ContractNetResponder;
import io.concord.core.proto.FailureException;
import io.concord.core.proto.FipaProtocols;
import io.concord.core.proto.RefuseException;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

/**
 * Sells one title: registers it in the DF ({@code book-selling}, named by the title, with its
 * price), answers contract-net CFPs for it with its price, and sells while it has stock.
 * Arguments: title, price, stock (default 1). Prints what it says.
 */
public class BookSeller extends Agent {
    private String title;
    private int price;
    private int stock;

    @Override
    protected void setup() {
        Object[] a = getArguments();
        if (a.length < 2) {
            throw new IllegalArgumentException("BookSeller needs (title, price[, stock])");
        }
        title = a[0].toString();
        price = Integer.parseInt(a[1].toString());
        stock = a.length > 2 ? Integer.parseInt(a[2].toString()) : 1;
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                Platform.of(myAgent).register(ServiceDescription.of("book-selling", title)
                                .withProperty("price", Integer.toString(price)))
                        .whenComplete((ok, e) -> System.out.println(getLocalName() + ": "
                                + (e == null ? "registered \"" + title + "\" at " + price + " with the DF"
                                : "could not register with the DF: " + e.getMessage())));
            }
        });
        addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET)) {
            @Override
            protected AclMessage handleCfp(AclMessage cfp) throws RefuseException {
                if (stock == 0 || !title.equals(cfp.getContent())) {
                    System.out.println(getLocalName() + ": REFUSE " + cfp.getContent());
                    throw new RefuseException("(not-available \"" + cfp.getContent() + "\")");
                }
                AclMessage propose = cfp.createReply();
                propose.setPerformative(Performative.PROPOSE);
                propose.setContent(Integer.toString(price));
                System.out.println(getLocalName() + ": PROPOSE " + price + " to " + cfp.getSender().localName());
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
                inform.setContent("(sold \"" + title + "\" " + price + ")");
                System.out.println(getLocalName() + ": INFORM sold \"" + title + "\" at " + price);
                return inform;
            }
        });
    }
}
