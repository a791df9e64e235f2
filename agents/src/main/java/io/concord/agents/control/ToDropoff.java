package io.concord.agents.control;

/** The patient on board, the chair drives to the drop-off node; there, the patient gets off ({@link Unloading}). */
final class ToDropoff extends Phase {
    ToDropoff(Task task, Context c) {
        super(task, TaskView.State.TO_DROPOFF);
        c.follow(task.toDropoff);
        c.say("drives " + task.id + " to node " + task.to + " by " + task.toDropoff);
        c.progress(task);
    }

    @Override
    Phase arrived(long nowMs, Context c) {
        return new Unloading(task, nowMs, c);
    }
}
