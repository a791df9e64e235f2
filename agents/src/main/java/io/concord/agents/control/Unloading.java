package io.concord.agents.control;

/** The patient gets off: the chair stands at the drop-off for the task's unloading time; then the task is done. */
final class Unloading extends Standing {
    Unloading(Task task, long nowMs, Context c) {
        super(task, TaskView.State.UNLOADING, nowMs, task.to, "gets off", c);
    }

    @Override
    Phase after(Context c) {
        c.finish(task, null);
        return null;
    }
}
