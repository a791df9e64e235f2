package io.concord.agents.control;

/**
 * The patient gets on: the chair stands at the pick-up for the task's loading time, then drives
 * to the drop-off ({@link ToDropoff}). The patient is on board from this phase on.
 */
final class Loading extends Phase {
    /** Until when (the chair's clock, ms) the patient gets on. */
    private final long untilMs;

    Loading(Task task, long nowMs, Context c) {
        super(task, TaskView.State.LOADING);
        untilMs = nowMs + (long) (task.unloadS * 1000);
        c.say("at node " + task.from + ": the patient gets on (" + (long) task.unloadS + " s)");
        c.progress(task);
    }

    @Override
    Phase reading(long nowMs, Context c) {
        return nowMs < untilMs ? this : new ToDropoff(task, c);
    }

    @Override
    boolean drives() {
        return false;
    }
}
