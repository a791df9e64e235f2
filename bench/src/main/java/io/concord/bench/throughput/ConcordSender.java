package io.concord.bench.throughput;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

/**
 * Sends INFORMs to one receiver as fast as it is let: 32 in each action of a cyclic behaviour.
 * Nothing paces it but the platform's flow control, which pauses it while the receiver lags.
 */
public final class ConcordSender extends Agent {
    private final AID to;
    private final String content;

    public ConcordSender(AID to, int bytes) {
        this.to = to;
        this.content = Counters.content(bytes);
    }

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                if (Counters.stopped()) {
                    myAgent.removeBehaviour(this);
                    return;
                }
                for (int i = 0; i < 32; i++) {
                    send(new AclMessage(Performative.INFORM).addReceiver(to).setContent(content));
                }
                Counters.SENT.addAndGet(32);
            }
        });
    }
}
