package io.concord.agents.control;

import java.util.List;

/**
 * One phase of a transport under way, in the manner of Open-RMF's task phases: each phase knows what
 * the chair does in it (drives a leg, or stands while the patient gets on or off) and which phase
 * follows it, and sets its task's state as it begins, so that the task's view and the progress
 * reports name it. {@link TaskRunner} only sequences them: it starts the first, hands each reading
 * and each arrival to the phase under way, and interrupts a phase to step aside for another chair
 * or to wait for a new plan (the phase goes on afterwards, toward its {@link #goal()}).
 *
 * <p>The sequence is {@link ToPickup}, {@link Loading}, {@link ToDropoff}, {@link Unloading} (the two
 * {@link Standing} phases stand while the patient gets on or off); the
 * task ends with the last (done), or earlier when it fails or is withdrawn.
 */
abstract sealed class Phase permits ToPickup, Standing, ToDropoff {
    /** What a phase may do: drive a leg, speak, report its task's progress, end its task. */
    interface Context {
        /** Drives the chair along {@code nodes} (the route follower's new leg). */
        void follow(List<Integer> nodes);

        /** Says something in the agent's log. */
        void say(String s);

        /** Tells whoever gave the task where it stands. */
        void progress(Task t);

        /** Ends the task: done ({@code failure} null) or failed. */
        void finish(Task t, String failure);
    }

    /** The task this phase is of. */
    final Task task;

    Phase(Task task, TaskView.State state) {
        this.task = task;
        task.state = state;
    }

    /** The phase after a reading at {@code nowMs} (the chair's clock): this one, the next (begun), or null once the task has ended. */
    Phase reading(long nowMs, Context c) {
        return this;
    }

    /** The phase after the chair reached the end of the leg it drove in this phase. */
    Phase arrived(long nowMs, Context c) {
        return this;
    }

    /** True while the chair drives in this phase; false while it stands (the route follower does not step). */
    boolean drives() {
        return true;
    }

    /** The node the task goes to next: the pick-up until the patient is on board, then the drop-off. */
    int goal() {
        return task.to;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "(" + task.id + ")";
    }
}
