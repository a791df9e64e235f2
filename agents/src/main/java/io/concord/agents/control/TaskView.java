package io.concord.agents.control;

/**
 * A control agent's task as others may read it (the console, a test).
 *
 * @param id       the Medical agent's task id
 * @param from     node where the patient is
 * @param to       node where the patient goes
 * @param priority TP
 * @param unloadS  seconds to load and to unload
 * @param state    where it stands
 * @param costS    the proposal's Cost (seconds until done, counting the queue)
 * @param pathS    the proposal's Path (seconds from pick-up to drop-off)
 * @param reason   why it was refused or failed, or why it is paused ("paused: the e-stop was pressed; ..."), or null
 */
public record TaskView(String id, int from, int to, double priority, double unloadS, State state, double costS,
                       double pathS, String reason) {

    /** The states of a task, in order. */
    public enum State {
        EVALUATING, PROPOSED, REFUSED, QUEUED, TO_PICKUP, LOADING, TO_DROPOFF, UNLOADING, DONE, FAILED, CANCELLED;

        /** True from the moment the chair is at the patient until the patient is off: the transport is never withdrawn then. */
        public boolean patientOnBoard() {
            return this == LOADING || this == TO_DROPOFF || this == UNLOADING;
        }
    }
}
