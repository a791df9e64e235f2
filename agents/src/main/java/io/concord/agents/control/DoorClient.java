package io.concord.agents.control;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.Door;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage.Here;
import io.concord.agents.proto.WheelchairMessage.OpenRequest;
import io.concord.agents.proto.WheelchairMessage.Passed;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.proto.FipaProtocols;

import java.util.Set;
import java.util.function.BiConsumer;
import java.util.function.Consumer;

/**
 * A control agent's side of the door agents (the twin of {@link TrafficClient}): a chair nearing a
 * door on its route asks the door to open (REQUEST {@code open}) and waits out of the leaf's way
 * until the door says it is open for it; once past the door it says so (INFORM {@code passed}),
 * and every {@link ControlAgent#KEEPALIVE_MS} it tells the doors still ahead that it means to pass
 * (INFORM {@code here}: a door's session lapses after 60 s of silence).
 *
 * <p>No transport of its own: it speaks through a {@link Doors} port, which the agent implements
 * over its yellow pages and its pending asks, and a test over a list.
 */
final class DoorClient {
    /** How far from a door's centre the chair asks it to open. */
    static final double ANNOUNCE_M = 4.0;
    /** How far from a door's centre the chair waits until the door is open for it. */
    static final double WAIT_AT_DOOR_M = 2.3;
    /** How far clear of a moving leaf the waiting chair's centre keeps: its half diagonal and its braking distance. */
    static final double LEAF_REACH_M = 1.2;
    /** How long a door may take to open for the chair before the route is planned around it. */
    static final long OPEN_TIMEOUT_MS = 60_000;

    /** How a door client reaches the doors. */
    interface Doors extends Outbox {
        /** The agent of door {@code id}, from the yellow pages, or null if it has none. */
        AID agentOf(String id);
    }

    private final Doors doors;
    private final HospitalMap map;
    /** The body the doors are told of (the chair's name). */
    private final String body;
    /** Told when a door cannot be passed: the node the chair last left, and why. */
    private final BiConsumer<Integer, String> onClosed;
    private final Consumer<String> say;

    /** The door asked to open for the chair, until it answers or the chair passes it. */
    private String asked;
    /** The door that said it is open for the chair. */
    private String granted;
    /** The door the chair is going through: told once the chair has reached the node past it. */
    private String passing;

    DoorClient(Doors doors, HospitalMap map, String body, BiConsumer<Integer, String> onClosed, Consumer<String> say) {
        this.doors = doors;
        this.map = map;
        this.body = body;
        this.onClosed = onClosed;
        this.say = say;
    }

    /**
     * Whether the chair, at {@code pose} on {@code edge} (which has a door) from node
     * {@code fromId}, may drive on: yes while far from the door, or once the door is open for it.
     * Near it, asks the door once to open, and holds the chair out of the leaf's way until the
     * door answers.
     */
    boolean mayEnter(Edge edge, int fromId, Pose pose) {
        String id = edge.door();
        if (id.equals(granted) || id.equals(passing)) {
            passing = id;
            return true;
        }
        Door d = map.door(id);
        double dist = pose.distanceTo(d.centre().x(), d.centre().y());
        if (dist > ANNOUNCE_M) {
            return true;
        }
        if (!id.equals(asked)) {
            AID agent = doors.agentOf(id);
            if (agent == null) {
                onClosed.accept(fromId, "door " + id + " has no agent");
                return false;
            }
            asked = id;
            AclMessage req = new AclMessage(Performative.REQUEST);
            req.addReceiver(agent);
            req.setProtocol(FipaProtocols.REQUEST);
            req.setOntology(Services.ONTOLOGY);
            req.setLanguage(Services.LANGUAGE);
            req.setContent(new OpenRequest(body).encode());
            say.accept("asks door " + id + " to open");
            doors.ask(req, OPEN_TIMEOUT_MS).thenAccept(a -> answered(id, fromId, a));
        }
        // Wait out of the leaf's way: beyond its sweep (a hinged leaf's quarter circle, on its swing
        // side, computed from its width; a revolving leaf's circle) by the chair's half diagonal and
        // its braking distance (at 2.2 m from a 3.2 m revolving door the nose of a chair that braked
        // there was inside the circle; a fixed 2.3 m let a 1.6 m hinged leaf open to 0.1 m of it).
        double wait = Math.max(WAIT_AT_DOOR_M, d.clearDistance(new Point(pose.x(), pose.y()), LEAF_REACH_M));
        return dist > wait;
    }

    private void answered(String id, int fromId, AclMessage a) {
        if (!id.equals(asked)) {
            return; // a request of a route given up since
        }
        if (a != null && a.getPerformative() == Performative.INFORM) {
            granted = id;
            say.accept("door " + id + " is open for it");
        } else {
            asked = null;
            onClosed.accept(fromId, "door " + id + (a == null ? " did not open within 60 s" : " answered " + a.getPerformative()
                    + ": " + ControlAgent.reason(a, "")));
        }
    }

    /** The chair reached the node at the end of {@code edge}: the door it went through is told. */
    void reached(Edge edge) {
        if (edge.door() != null && edge.door().equals(passing)) {
            AID agent = doors.agentOf(passing);
            if (agent != null) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(agent);
                m.setOntology(Services.ONTOLOGY);
                m.setLanguage(Services.LANGUAGE);
                m.setContent(new Passed(body).encode());
                doors.send(m);
            }
            passing = null;
            granted = null;
            asked = null;
        }
    }

    /** A new route: no door asked or granted yet (a door being passed is still told once passed). */
    void newRoute() {
        asked = null;
        granted = null;
    }

    /** Tells each door of {@code ahead} that the chair still means to pass. */
    void keepAlive(Set<String> ahead) {
        for (String id : ahead) {
            AID agent = doors.agentOf(id);
            if (agent != null) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(agent);
                m.setOntology(Services.ONTOLOGY);
                m.setLanguage(Services.LANGUAGE);
                m.setContent(new Here(body, null).encode());
                doors.send(m);
            }
        }
    }
}
