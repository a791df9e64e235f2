package io.concord.agents.control;

/** The patient gets off: the chair stands at the drop-off for the task's unloading time; then the task is done. */
final class Unloading extends Phase {
    /** Until when (the chair's clock, ms) the patient gets off. */
    private final long untilMs;

    Unloading(Task task, long nowMs, Context c) {
        super(task, TaskView.State.UNLOADING);
        untilMs = nowMs + (long) (task.unloadS * 1000);
        c.say("at node " + task.to + ": the patient gets off (" + (long) task.unloadS + " s)");
        c.progress(task);
    }

    @Override
    Phase reading(long nowMs, Context c) {
        if (nowMs < untilMs) {
            return this;
        }
        c.finish(task, null);
        return null;
    }

    @Override
    boolean drives() {
        return false;
    }
}
