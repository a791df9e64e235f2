package io.concord.bench.throughput;

import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

/** Takes every message from its mailbox and counts it. */
public final class ConcordReceiver extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                int n = 0;
                while (receive() != null) {
                    n++;
                }
                if (n > 0) {
                    Counters.RECEIVED.addAndGet(n);
                }
                block();
            }
        });
    }
}
