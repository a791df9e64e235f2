import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.TickerBehaviour;
import jade.core.behaviours.WakerBehaviour;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ContractNetInitiator;

import java.util.Vector;

/**
 * A tick-driven market: every 300 ms it clears its book (400 ms of work, longer than the period),
 * then buys from the cheapest of three sellers by a contract net. The market closes at 1.5 s.
 * On JADE a tick comes a period after the last one ended, so two rounds fit before the close and
 * both orders are done; a ticker that made up for lost time would start a third round at once,
 * each one, and starve the contract nets.
 */
public class Market extends Agent {
    private int rounds;
    private int orders;
    private TickerBehaviour ticker;

    @Override
    protected void setup() {
        ticker = new TickerBehaviour(this, 300) {
            @Override
            protected void onTick() {
                rounds++;
                long t = System.nanoTime();
                while (System.nanoTime() - t < 400_000_000L) {
                    // clearing the book
                }
                ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
                cfp.setProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET);
                cfp.setContent(Integer.toString(rounds));
                for (String s : new String[] {"s1", "s2", "s3"}) {
                    cfp.addReceiver(new AID(s, AID.ISLOCALNAME));
                }
                myAgent.addBehaviour(new ContractNetInitiator(myAgent, cfp) {
                    @Override
                    protected void handleAllResponses(Vector responses, Vector acceptances) {
                        ACLMessage best = null;
                        for (Object o : responses) {
                            ACLMessage r = (ACLMessage) o;
                            if (r.getPerformative() == ACLMessage.PROPOSE
                                    && (best == null || Integer.parseInt(r.getContent()) < Integer.parseInt(best.getContent()))) {
                                best = r;
                            }
                        }
                        for (Object o : responses) {
                            ACLMessage r = (ACLMessage) o;
                            ACLMessage reply = r.createReply();
                            reply.setPerformative(r == best ? ACLMessage.ACCEPT_PROPOSAL : ACLMessage.REJECT_PROPOSAL);
                            acceptances.add(reply);
                        }
                    }

                    @Override
                    protected void handleInform(ACLMessage inform) {
                        orders++;
                        System.out.println("order " + orders + " from " + inform.getSender().getLocalName() + " at " + inform.getContent());
                    }
                });
            }
        };
        addBehaviour(ticker);
        addBehaviour(new WakerBehaviour(this, 1500) {
            @Override
            protected void onWake() {
                System.out.println("at the close: " + rounds + " rounds, " + orders + " orders");
                ticker.stop();
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
