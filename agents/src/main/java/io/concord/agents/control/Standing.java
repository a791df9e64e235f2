package io.concord.agents.control;

/**
 * A phase in which the chair stands at a node while the patient gets on or off, for the task's
 * loading time (the chair's clock), and then the phase that follows begins.
 */
abstract sealed class Standing extends Phase permits Loading, Unloading {
    /** Until when (the chair's clock, ms) the chair stands. */
    private final long untilMs;

    Standing(Task task, TaskView.State state, long nowMs, int node, String what, Context c) {
        super(task, state);
        untilMs = nowMs + (long) (task.unloadS * 1000);
        c.say("at node " + node + ": the patient " + what + " (" + (long) task.unloadS + " s)");
        c.progress(task);
    }

    /** The phase once the patient is on or off: the next (begun), or null once the task has ended. */
    abstract Phase after(Context c);

    @Override
    final Phase reading(long nowMs, Context c) {
        return nowMs < untilMs ? this : after(c);
    }

    @Override
    final boolean drives() {
        return false;
    }
}
