package io.concord.bench.concord;

import io.concord.bench.support.Rounds;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

import java.util.List;

/** The book buyer and sellers on Concord, with exactly the rules of the JADE version. */
public final class ConcordBooks {
    private ConcordBooks() {
    }

    /** Answers QUERY-REF with its price and REQUEST with AGREE. */
    public static class Seller extends Agent {
        private final String price;

        public Seller(int price) {
            this.price = Integer.toString(price);
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
                    boolean query = m.getPerformative() == Performative.QUERY_REF;
                    AclMessage reply = m.createReply();
                    reply.setPerformative(query ? Performative.INFORM : Performative.AGREE);
                    reply.setContent(query ? price : "ok");
                    send(reply);
                }
            });
        }
    }

    /** Asks every seller, waits for all quotes (or the timeout), requests from the cheapest. */
    public static class Buyer extends Agent {
        private final Rounds rounds;
        private final long timeoutMs;
        /** The sellers, set before the first round. */
        public volatile List<AID> sellers;
        private int round;
        private int quotes;
        private int best;
        private AID bestSeller;
        private long deadlineMs;
        private boolean requested;

        public Buyer(Rounds rounds, long timeoutMs) {
            this.rounds = rounds;
            this.timeoutMs = timeoutMs;
        }

        /** Starts a round; call on the runtime's loop. */
        public void startRound() {
            round++;
            quotes = 0;
            bestSeller = null;
            requested = false;
            deadlineMs = currentTimeMillis() + timeoutMs;
            AclMessage q = new AclMessage(Performative.QUERY_REF);
            sellers.forEach(q::addReceiver);
            q.setConversationId("r" + round);
            q.setContent("(price (book \"The Art of Agents\"))");
            send(q);
        }

        private void request() {
            requested = true;
            AclMessage r = new AclMessage(Performative.REQUEST).addReceiver(bestSeller);
            r.setConversationId("r" + round);
            r.setContent("(buy (book \"The Art of Agents\"))");
            send(r);
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m = receive(MessageTemplate.matchConversationId("r" + round));
                    if (m == null) {
                        long left = deadlineMs - currentTimeMillis();
                        if (!requested && round > 0 && left <= 0) {
                            request();
                        } else {
                            block(Math.max(1, left));
                        }
                        return;
                    }
                    if (m.getPerformative() == Performative.INFORM && !requested) {
                        int p = Integer.parseInt(m.getContent());
                        if (bestSeller == null || p < best) {
                            best = p;
                            bestSeller = m.getSender();
                        }
                        if (++quotes == sellers.size()) {
                            request();
                        }
                    } else if (m.getPerformative() == Performative.AGREE && rounds.roundDone()) {
                        startRound();
                    }
                }
            });
        }
    }
}
