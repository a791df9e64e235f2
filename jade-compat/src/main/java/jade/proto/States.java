package jade.proto;

import jade.core.behaviours.Behaviour;
import jade.core.behaviours.DataStore;

/**
 * The behaviours a protocol's {@code registerXxx(Behaviour)} puts in place of one of its steps.
 * JADE's protocols are FSMs whose steps are states; here a protocol is one behaviour, so a
 * registered step runs on the spot, on the agent's thread, until it is done: it shares the
 * protocol's data store (it reads the protocol's keys, the request, and puts its answer under
 * the key JADE names), and a step that blocks is run again every millisecond until it is done.
 */
final class States {
    private States() {
    }

    /**
     * Runs {@code step} (if not null) to its end, with the protocol's agent and data store, after
     * taking {@code outKey} (where it puts its answer; may be null) out of the store; true if it ran.
     */
    static boolean run(Behaviour owner, Behaviour step, DataStore store, Object outKey) {
        if (step == null) {
            return false;
        }
        if (outKey != null) {
            store.remove(outKey);
        }
        step.setAgent(owner.getAgent());
        step.setDataStore(store);
        step.reset();
        do {
            step.actionWrapper();
            if (!step.done() && !step.isRunnable()) {
                try {
                    Thread.sleep(1);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted while the registered step " + step.getBehaviourName() + " ran", e);
                }
                step.restart();
            }
        } while (!step.done());
        step.onEnd();
        return true;
    }
}
