package io.concord.bench.jade;

import io.concord.bench.support.Rounds;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * The book buyer and sellers on JADE, speaking what Concord's annex agents speak
 * ({@code io.concord.examples.BookBuyer} and {@code BookSeller}, which the benchmark runs on
 * Concord): QUERY-REF to every seller, the quotes within a second, REQUEST {@code 1} to the
 * cheapest, AGREE. Left out, since the benchmark never meets them: the buyer's new attempt after
 * a REFUSE, a price above 80 or an order nobody answers, and the sellers' REFUSE and
 * NOT-UNDERSTOOD.
 */
public final class JadeBooks {
    private JadeBooks() {
    }

    /** Answers QUERY-REF with its price and an order (REQUEST) with AGREE. Arguments: price, Rounds. */
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
                    boolean query = m.getPerformative() == ACLMessage.QUERY_REF;
                    if (!query && m.getPerformative() != ACLMessage.REQUEST) {
                        return;
                    }
                    ACLMessage reply = m.createReply();
                    reply.setPerformative(query ? ACLMessage.INFORM : ACLMessage.AGREE);
                    if (query) {
                        reply.setContent(price);
                    }
                    send(reply);
                }
            });
            if (getArguments().length > 1) {
                ((Rounds) getArguments()[1]).agentReady();
            }
        }
    }

    /**
     * Asks every seller, waits for all quotes (or a second), orders one book from the cheapest,
     * waits for its AGREE. Arguments: Rounds, S, timeout ms.
     */
    public static class Buyer extends Agent {
        private Rounds rounds;
        private int sellers;
        private long timeoutMs;
        private int attempt;
        private String conversation;
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
                    ACLMessage m = conversation == null ? null : receive(MessageTemplate.MatchConversationId(conversation));
                    if (m == null) {
                        long left = deadline - System.currentTimeMillis();
                        if (!requested && conversation != null && left <= 0) {
                            request();
                        } else {
                            block(Math.max(1, left));
                        }
                        return;
                    }
                    if (m.getPerformative() == ACLMessage.INFORM && !requested) {
                        int p = Integer.parseInt(m.getContent().trim());
                        if (bestSeller == null || p < best) {
                            best = p;
                            bestSeller = m.getSender();
                        }
                        if (++quotes == sellers) {
                            request();
                        }
                    } else if (m.getPerformative() == ACLMessage.AGREE && m.getSender().equals(bestSeller)) {
                        if (rounds.roundDone()) {
                            startRound();
                        }
                    }
                }
            });
            rounds.agentReady();
        }

        private void startRound() {
            attempt++;
            conversation = "books-" + getLocalName() + "-" + attempt;
            quotes = 0;
            bestSeller = null;
            requested = false;
            deadline = System.currentTimeMillis() + timeoutMs;
            ACLMessage q = new ACLMessage(ACLMessage.QUERY_REF);
            for (int i = 0; i < sellers; i++) {
                q.addReceiver(new AID("seller" + i, AID.ISLOCALNAME));
            }
            q.setConversationId(conversation);
            q.setReplyWith(conversation + "-q");
            q.setContent("(price (book \"The Art of Agents\"))");
            send(q);
        }

        private void request() {
            requested = true;
            ACLMessage r = new ACLMessage(ACLMessage.REQUEST);
            r.addReceiver(bestSeller);
            r.setConversationId(conversation);
            r.setContent("1");
            send(r);
        }
    }
}
