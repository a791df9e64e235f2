package io.concord.agents.control;

/** To the patient: the chair drives to the pick-up node; there, the patient gets on ({@link Loading}). */
final class ToPickup extends Phase {
    ToPickup(Task task) {
        super(task, TaskView.State.TO_PICKUP);
    }

    @Override
    Phase arrived(long nowMs, Context c) {
        return new Loading(task, nowMs, c);
    }

    @Override
    int goal() {
        return task.from;
    }
}
