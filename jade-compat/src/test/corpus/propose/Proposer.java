import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ProposeInitiator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Date;
import java.util.List;
import java.util.Vector;

/**
 * Proposes a price with a ProposeInitiator: first to three partners who accept, reject and do not
 * understand; then to one who stays silent and one who chats, with a deadline. The answers come in
 * any order, so each round prints them sorted, once all are in.
 */
public class Proposer extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new Round(this, proposal("30 euros", "accept", "reject", "puzzled"), 1));
    }

    private ACLMessage proposal(String content, String... to) {
        ACLMessage m = new ACLMessage(ACLMessage.PROPOSE);
        for (String t : to) {
            m.addReceiver(new AID(t, AID.ISLOCALNAME));
        }
        m.setProtocol(FIPANames.InteractionProtocol.FIPA_PROPOSE);
        m.setContent(content);
        return m;
    }

    private class Round extends ProposeInitiator {
        private final int round;
        private final List<String> seen = new ArrayList<>();

        Round(Agent a, ACLMessage msg, int round) {
            super(a, msg);
            this.round = round;
        }

        @Override
        protected Vector prepareInitiations(ACLMessage propose) {
            System.out.println("round " + round + ": proposing " + propose.getContent());
            return super.prepareInitiations(propose);
        }

        @Override
        protected void handleAcceptProposal(ACLMessage accept) {
            seen.add("accepted by " + accept.getSender().getLocalName() + ": " + accept.getContent());
        }

        @Override
        protected void handleRejectProposal(ACLMessage reject) {
            seen.add("rejected by " + reject.getSender().getLocalName() + ": " + reject.getContent());
        }

        @Override
        protected void handleNotUnderstood(ACLMessage notUnderstood) {
            seen.add("not understood by " + notUnderstood.getSender().getLocalName());
        }

        @Override
        protected void handleOutOfSequence(ACLMessage msg) {
            seen.add("out of sequence from " + msg.getSender().getLocalName() + ": "
                    + ACLMessage.getPerformative(msg.getPerformative()) + " " + msg.getContent());
        }

        @Override
        protected void handleAllResponses(Vector responses) {
            Collections.sort(seen);
            for (String s : seen) {
                System.out.println("round " + round + ": " + s);
            }
            System.out.println("round " + round + ": " + responses.size() + " responses");
            if (round == 1) {
                ACLMessage next = proposal("40 euros", "silent", "chatty");
                next.setReplyByDate(new Date(System.currentTimeMillis() + 3000));
                myAgent.addBehaviour(new Round(myAgent, next, 2));
            } else {
                myAgent.doDelete();
            }
        }
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
