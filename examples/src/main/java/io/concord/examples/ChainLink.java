package io.concord.examples;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.Agent;

/**
 * A link of the dissertation's chain ("pass the secret", annex B): a QUERY-REF that comes in is
 * passed on, with its content, as a QUERY-REF to the next link. The first link starts each round
 * with the round's number and checks that it comes back unchanged.
 *
 * <p>Boot arguments: {@code ChainLink(next)} for a link, {@code ChainLink(next, rounds)} for the
 * first; {@code next} is {@code name} or {@code name@platform=http://host:port/acc}. The first link
 * prints {@code chain: N rounds ... mean X us a round} at the end.
 */
public class ChainLink extends Agent {
    private AID next;
    private int rounds;
    private int round;
    private long roundStartNs;
    private long totalNs;
    private int retries;

    @Override
    protected void setup() {
        Object[] a = getArguments();
        if (a.length < 1 || a[0].toString().isBlank()) {
            throw new IllegalArgumentException("ChainLink(next[, rounds]): name the next link");
        }
        next = Receivers.parse(a[0].toString(), getAID());
        if (a.length > 1) {
            rounds = Integer.parseInt(a[1].toString().trim());
        }
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                AclMessage m = receive();
                if (m == null) {
                    if (rounds > 0 && round == 0) {
                        if (!Receivers.listed(myAgent, java.util.List.of(next))) {
                            block(100); // the next link has not started yet
                            return;
                        }
                        round = 1;
                        pass(Integer.toString(round));
                    }
                    block();
                    return;
                }
                handle(m);
            }
        });
    }

    private void handle(AclMessage m) {
        if (m.getPerformative() == Performative.FAILURE && rounds > 0 && retries < 50) {
            // The next link may not have started yet: the round is sent again a little later.
            retries++;
            addBehaviour(new io.concord.core.agent.WakerBehaviour(this, 200) {
                @Override
                protected void onWake() {
                    pass(Integer.toString(round));
                }
            });
            return;
        }
        if (m.getPerformative() != Performative.QUERY_REF) {
            return;
        }
        if (rounds == 0) {
            pass(m.getContent());
            return;
        }
        if (!Integer.toString(round).equals(m.getContent())) {
            System.out.println(getLocalName() + ": round " + round + " came back as '" + m.getContent() + "'; stopping");
            rounds = -1;
            return;
        }
        totalNs += runtime().clock().nanoTime() - roundStartNs;
        if (round == rounds) {
            System.out.println(getLocalName() + ": chain: " + rounds + " rounds through " + next.name() + " and back, mean "
                    + (totalNs / rounds / 1000) + " us a round");
            rounds = -1;
            return;
        }
        round++;
        pass(Integer.toString(round));
    }

    private void pass(String content) {
        roundStartNs = runtime().clock().nanoTime();
        AclMessage m = new AclMessage(Performative.QUERY_REF).addReceiver(next);
        m.setContent(content);
        send(m);
    }
}
