package io.concord.agents.control;

import java.util.List;

/**
 * The chair stands until a new plan comes, to the interrupted phase's {@link #goal}: its route broke (a
 * door that did not open, an edge blocked, a route the traffic agent cannot grant), it made way
 * elsewhere than its goal, or its task starts away from where it was planned. The plan's answer
 * decides what follows: the phase it interrupted, along the new plan, or the task's failure and why.
 */
final class Replanning extends Interruption {
    /** Why it replans, said with a failure (null: nothing went wrong, it only starts elsewhere). */
    private final String why;

    Replanning(Phase resume, String why) {
        super(resume);
        this.why = why;
    }

    @Override
    boolean awaitsPlan() {
        return true;
    }

    /**
     * The planner's answer: {@code nodes} (from where it stands), or null and {@code refusal}, why
     * none came. The phase after it: the one it interrupted, driving the new plan; or null once the
     * task has failed.
     */
    Phase answered(List<Integer> nodes, String refusal, Context c) {
        if (nodes == null) {
            c.finish(task, refusal + (why == null ? "" : " (" + why + ")"));
            return null;
        }
        // Back along the edge it was on to the node the new plan starts from (the last one it
        // reached), then along the new plan.
        c.followBack(nodes);
        c.say("new plan " + nodes);
        return resume;
    }
}
