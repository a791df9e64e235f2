package io.concord.agents.control;

/**
 * The patient gets on: the chair stands at the pick-up for the task's loading time, then drives
 * to the drop-off ({@link ToDropoff}). The patient is on board from this phase on.
 */
final class Loading extends Standing {
    Loading(Task task, long nowMs, Context c) {
        super(task, TaskView.State.LOADING, nowMs, task.from, "gets on", c);
    }

    @Override
    Phase after(Context c) {
        return new ToDropoff(task, c);
    }
}
