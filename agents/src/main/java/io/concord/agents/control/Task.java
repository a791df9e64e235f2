package io.concord.agents.control;

import io.concord.core.acl.AclMessage;

import java.util.List;

/** A patient transport as a control agent holds it, from the CFP to its end. */
final class Task {
    final String id;
    final int from;
    final int to;
    final double priority;
    final double unloadS;
    final AclMessage cfp;
    AclMessage accept;
    List<Integer> toPickup;
    List<Integer> toDropoff;
    double pathS;
    double costS;
    double estimateS;
    TaskView.State state = TaskView.State.EVALUATING;
    String reason;
    /** Why it is paused (the chair is held), or null. */
    String paused;
    int start;

    Task(String id, int from, int to, double priority, double unloadS, AclMessage cfp) {
        this.id = id;
        this.from = from;
        this.to = to;
        this.priority = priority;
        this.unloadS = unloadS;
        this.cfp = cfp;
    }

    TaskView view() {
        return new TaskView(id, from, to, priority, unloadS, state, costS, pathS, paused != null ? "paused: " + paused : reason);
    }
}
