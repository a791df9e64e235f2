package io.concord.bench.jade;

import io.concord.bench.support.Rounds;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** The book buyer and sellers on JADE, with the same conversation rules as the Concord version. */
public final class JadeBooks {
    private JadeBooks() {
    }

    /** Answers QUERY-REF with its price and REQUEST with AGREE. Arguments: price, Rounds. */
    public static class Seller extends Agent {
        @Override
        protected void setup() {
            String price = String.valueOf(getArguments()[0]);
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    ACLMessage m = receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    ACLMessage reply = m.createReply();
                    reply.setPerformative(m.getPerformative() == ACLMessage.QUERY_REF ? ACLMessage.INFORM : ACLMessage.AGREE);
                    reply.setContent(m.getPerformative() == ACLMessage.QUERY_REF ? price : "ok");
                    send(reply);
                }
            });
            if (getArguments().length > 1) {
                ((Rounds) getArguments()[1]).agentReady();
            }
        }
    }

    /**
     * Asks every seller, waits for all quotes (or the timeout), requests from the cheapest, waits
     * for its AGREE. Arguments: Rounds, S, timeout ms.
     */
    public static class Buyer extends Agent {
        private Rounds rounds;
        private int sellers;
        private long timeoutMs;
        private int round;
        private int quotes;
        private int best;
        private AID bestSeller;
        private long deadline;
        private boolean requested;

        @Override
        protected void setup() {
            rounds = (Rounds) getArguments()[0];
            sellers = (Integer) getArguments()[1];
            timeoutMs = (Long) getArguments()[2];
            setEnabledO2ACommunication(true, 0);
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    if (getO2AObject() != null) {
                        startRound();
                        return;
                    }
                    ACLMessage m = receive(MessageTemplate.MatchConversationId("r" + round));
                    if (m == null) {
                        long left = deadline - System.currentTimeMillis();
                        if (!requested && round > 0 && left <= 0) {
                            request();
                        } else {
                            block(Math.max(1, left));
                        }
                        return;
                    }
                    if (m.getPerformative() == ACLMessage.INFORM && !requested) {
                        int p = Integer.parseInt(m.getContent());
                        if (bestSeller == null || p < best) {
                            best = p;
                            bestSeller = m.getSender();
                        }
                        if (++quotes == sellers) {
                            request();
                        }
                    } else if (m.getPerformative() == ACLMessage.AGREE) {
                        if (rounds.roundDone()) {
                            startRound();
                        }
                    }
                }
            });
            rounds.agentReady();
        }

        private void startRound() {
            round++;
            quotes = 0;
            bestSeller = null;
            requested = false;
            deadline = System.currentTimeMillis() + timeoutMs;
            ACLMessage q = new ACLMessage(ACLMessage.QUERY_REF);
            for (int i = 0; i < sellers; i++) {
                q.addReceiver(new AID("seller" + i, AID.ISLOCALNAME));
            }
            q.setConversationId("r" + round);
            q.setContent("(price (book \"The Art of Agents\"))");
            send(q);
        }

        private void request() {
            requested = true;
            ACLMessage r = new ACLMessage(ACLMessage.REQUEST);
            r.addReceiver(bestSeller);
            r.setConversationId("r" + round);
            r.setContent("(buy (book \"The Art of Agents\"))");
            send(r);
        }
    }
}
