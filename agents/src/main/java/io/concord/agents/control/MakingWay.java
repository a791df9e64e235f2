package io.concord.agents.control;

import java.util.List;

/**
 * The chair drives to a node the traffic agent named ({@link #to}), out of its route: first it
 * stands while the way there is planned (over nodes nobody holds, the way the traffic agent chose),
 * then drives it. There, the phase it interrupted goes on: at once if that phase's goal is this
 * node, else after a plan from here to that goal; an idle chair stays.
 */
abstract sealed class MakingWay extends Interruption permits StepAside, GoingHome {
    /** Where it makes way to. */
    final int to;
    private boolean planned;

    MakingWay(Phase resume, int to) {
        super(resume);
        this.to = to;
    }

    @Override
    final boolean awaitsPlan() {
        return !planned;
    }

    /** What it says as it drives there by {@code nodes}. */
    abstract String drives(List<Integer> nodes);

    /** The way is planned ({@code nodes}, from where it stands to {@link #to}): the chair drives it. */
    final void planned(List<Integer> nodes, Context c) {
        planned = true;
        c.say(drives(nodes));
        c.follow(nodes);
    }

    @Override
    final Phase arrived(long nowMs, Context c) {
        c.clearRoute();
        c.say("has made way at node " + to);
        if (resume == null) {
            return null; // idle here: said on the next reading
        }
        int goal = resume.goal();
        if (goal != to) {
            c.standAt(to);
            return c.replan(resume, to, goal, null);
        }
        return resume.arrived(nowMs, c);
    }
}
