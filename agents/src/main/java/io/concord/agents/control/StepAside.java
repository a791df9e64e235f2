package io.concord.agents.control;

import java.util.List;

/**
 * The traffic agent's order to make way for another chair (to break a deadlock, or to clear a node
 * another chair needs): the chair with a task drives to the node it names, and its task's phase
 * goes on from there.
 */
final class StepAside extends MakingWay {
    StepAside(Phase resume, int to) {
        super(resume, to);
    }

    @Override
    String drives(List<Integer> nodes) {
        return "makes way for another chair: to node " + to + " by " + nodes;
    }
}
