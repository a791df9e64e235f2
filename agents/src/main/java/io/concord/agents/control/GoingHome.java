package io.concord.agents.control;

import java.util.List;

/**
 * An idle chair sent home by the traffic agent (idle off the map's parking places, in a patient's
 * room, say), or out of another's way: it drives to the node named, and stands idle there. A
 * task given meanwhile waits until it has got there.
 */
final class GoingHome extends MakingWay {
    /** False when the order is to make way for another chair, to a node that is no parking place. */
    private final boolean parking;

    GoingHome(int to) {
        this(to, true);
    }

    GoingHome(int to, boolean parking) {
        super(null, to);
        this.parking = parking;
    }

    @Override
    String drives(List<Integer> nodes) {
        return parking ? "goes home: to parking place " + to + " by " + nodes
                : "makes way for another chair (it is idle): to node " + to + " by " + nodes;
    }
}
