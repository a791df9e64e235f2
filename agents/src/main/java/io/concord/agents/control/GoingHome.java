package io.concord.agents.control;

import java.util.List;

/**
 * An idle chair sent home by the traffic agent (idle off the map's parking places, in a patient's
 * room, say): it drives to the parking place named, and stands idle there. A task given meanwhile
 * waits until it has parked.
 */
final class GoingHome extends MakingWay {
    GoingHome(int to) {
        super(null, to);
    }

    @Override
    String drives(List<Integer> nodes) {
        return "goes home: to parking place " + to + " by " + nodes;
    }
}
