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
 * task ends with the last (done), or earlier when it fails or is withdrawn. An {@link Interruption}
 * stands in for the phase under way for a while, and then that phase goes on: {@link StepAside}
 * (the traffic agent's order to make way for another chair), {@link Replanning} (the chair stands
 * until a new plan comes); an idle chair's {@link GoingHome} interrupts no task.
 */
abstract sealed class Phase permits ToPickup, Standing, ToDropoff, Interruption {
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

        /** Back along the edge the chair is on to the first node of {@code nodes}, then along them: never across the floor off the graph. */
        void followBack(List<Integer> nodes);

        /** The chair stands at {@code node}, with no leg to drive (until a new plan comes). */
        void standAt(int node);

        /** The chair has no route (the leg it drove is over). */
        void clearRoute();

        /**
         * Asks for a plan from {@code from} to {@code goal} for the task of {@code resume}, which goes on
         * along it once it comes: the {@link Replanning} under way until then, or null if none can be
         * asked (the task has failed).
         */
        Phase replan(Phase resume, int from, int goal, String why);
    }

    /** The task this phase is of (null only for an idle chair's {@link GoingHome}). */
    final Task task;

    Phase(Task task, TaskView.State state) {
        this.task = task;
        task.state = state;
    }

    /** A phase that leaves its task's state as it is (an interruption of another phase). */
    Phase(Task task) {
        this.task = task;
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
        return getClass().getSimpleName() + "(" + (task == null ? "idle" : task.id) + ")";
    }
}
