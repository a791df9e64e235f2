package io.concord.agents.control;

import io.concord.agents.chair.ObstacleFilter;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Localiser;
import io.concord.agents.chair.Pose;
import io.concord.agents.chair.PoseController;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Drives a chair along a route of the map's nodes, reading by reading: on the graph's line from
 * node to node, over the {@link PoseController} and the {@link Localiser} (odometry corrected by
 * the floor markers). Its commands go through an {@link ObstacleFilter}, which keeps the stop and
 * slow zones whatever the route; stopped by it on an edge for {@link #BLOCKED_AFTER_MS}, the
 * follower reports the edge blocked. Before it moves it asks its
 * {@link Way} (the traffic agent and the doors, in the agent), and tells it where it sets off to
 * and which node it reached.
 *
 * <p>It commands the chair it is given and nothing else: no messages, no clock of its own (the
 * readings' time is the chair's clock).
 */
final class RouteFollower {
    /** Within this of where a door's edge starts, the chair turns square to it on the spot before it drives. */
    static final double DOOR_SQUARE_M = 0.3;
    /** Stopped this long on an edge, the edge is reported blocked. */
    static final long BLOCKED_AFTER_MS = 15_000;

    /** What the follower asks and tells before and as it moves. */
    interface Way {
        /** Whether the chair may drive this very {@code route} now, standing on {@code standsOn}. */
        boolean mayDrive(List<Integer> route, List<Integer> standsOn);

        /** Whether the chair, at a node, may set off to node {@code index} of {@code route} (its turn there). */
        boolean mayGoOn(List<Integer> route, int index);

        /** Whether the chair at {@code pose} may drive on along {@code edge} (which has a door) from {@code fromId}. */
        boolean mayEnter(Edge edge, int fromId, Pose pose);

        /** The chair sets off along an edge: it now stands on both its ends. */
        void setOff(List<Integer> standsOn);

        /**
         * The chair reached a node: by {@code edge} (null for the first node of a route it drove
         * back to); {@code rest} is the route from that node on.
         */
        void reached(Edge edge, List<Integer> rest);
    }

    /** What the follower reports. */
    interface Events {
        /** The route's last node is reached; the chair is stopped. */
        void arrived(long nowMs);

        /** The route cannot be driven from node {@code fromId}: a new plan is needed. */
        void broken(int fromId, String why);

        /** The edge has been blocked for {@link #BLOCKED_AFTER_MS}. */
        void blocked(int fromId, int toId);

        /** Something worth a line in the log. */
        void say(String s);
    }

    private final ObstacleFilter chair;
    private final HospitalMap map;
    private final PoseController control = new PoseController(60, 30, 0.12, Math.toRadians(5));
    private final Localiser localiser = new Localiser();

    private List<Integer> route;
    /** The node of {@link #route} it drives to; 0: back to the route's first node. */
    private int index;
    private int lastNode = -1;
    /** The node the chair drives to on the edge it is on, or -1 at a node. */
    private int edgeTo = -1;
    private long stoppedSinceMs = -1;
    /**
     * Stopped on an edge for {@link #BLOCKED_AFTER_MS} with its heading more than this off the way to
     * where it drives, the chair first turns on the spot to face it (a turn on the spot passes the
     * obstacle filter) and calls the edge blocked only if it is still stopped {@link #BLOCKED_AFTER_MS}
     * after (depot seed 190: at a node of a one-lane corridor, come out of a revolving door and turned
     * 15 degrees past its way, a chair's front infrared read the wall at 0.24 m, and the small
     * steering of a drive forward never came, for ever).
     */
    static final double FACE_AFTER_STOP_RAD = Math.toRadians(5);
    /** Turning on the spot to face where it drives, after a long stop ({@link #FACE_AFTER_STOP_RAD}), since then (ms); it stops turning after {@link #BLOCKED_AFTER_MS}. */
    private boolean facing;
    private long facingSinceMs;
    /** It has turned to face its way on this edge once: the next long stop is the edge blocked. */
    private boolean faced;

    RouteFollower(ObstacleFilter chair, HospitalMap map) {
        this.chair = chair;
        this.map = map;
    }

    /** Takes a reading into the chair's pose; returns where the chair is believed to be. */
    Pose locate(ChairReadings r) {
        return localiser.update(r);
    }

    /** Where it believes the chair is, or null before the first reading. */
    Pose pose() {
        return localiser.pose();
    }

    /** Follows {@code nodes}, which start at the node the chair stands at. */
    void follow(List<Integer> nodes) {
        route = new ArrayList<>(nodes);
        index = 1;
        stoppedSinceMs = -1;
        facing = false;
        faced = false;
        lastNode = nodes.get(0);
    }

    /** Follows {@code nodes} after driving back along the edge it is on to their first node. */
    void followBack(List<Integer> nodes) {
        follow(nodes);
        index = 0;
    }

    /** Holds {@code nodes} as its route without driving them (it waits there, a new plan to come). */
    void hold(List<Integer> nodes) {
        route = nodes;
        facing = false;
        faced = false;
    }

    /** Keeps only the part of the route not yet driven (the edge it is on included). */
    void trim() {
        int cut = Math.max(0, index - 1);
        route = new ArrayList<>(route.subList(cut, route.size()));
        index -= cut; // still on the same edge (or driving back to the same first node)
    }

    /** True if it has a route still to drive that ends at {@code goal} (not one held to wait on). */
    boolean leadsTo(int goal) {
        return route != null && route.size() >= 2 && route.get(route.size() - 1) == goal && index < route.size();
    }

    /** Drops the route; the next steps stop the chair. */
    void clear() {
        route = null;
        facing = false;
        faced = false;
    }

    /** The route, or null. */
    List<Integer> route() {
        return route;
    }

    /** The part of the route not yet driven (the edge it is on included), or an empty list. */
    List<Integer> ahead() {
        return route == null ? List.of() : route.subList(Math.max(0, index - 1), route.size());
    }

    /** Whether the route has nodes still to reach. */
    boolean underWay() {
        return route != null && index < route.size();
    }

    /** The last node of the route. */
    int goal() {
        return route.get(route.size() - 1);
    }

    /** The node the chair stands at or last reached. */
    int here() {
        return lastNode >= 0 ? lastNode : nearestNode();
    }

    /** The nodes the chair stands on: the last it reached, and the one it drives to if it is on an edge. */
    List<Integer> standsOn() {
        List<Integer> at = new ArrayList<>();
        at.add(here());
        if (edgeTo >= 0 && edgeTo != at.get(0)) {
            at.add(edgeTo);
        }
        return at;
    }

    /** The node nearest the chair (by its pose, or by its last reading before it has one). */
    int nearestNode() {
        Pose p = localiser.pose();
        if (p == null) {
            ChairReadings r = chair.latest();
            p = r == null ? null : r.fix() != null ? r.fix() : r.odometry();
        }
        int best = -1;
        double bd = Double.MAX_VALUE;
        for (Node n : map.nodes()) {
            double d = p == null ? 0 : p.distanceTo(n.at().x(), n.at().y());
            if (d < bd) {
                bd = d;
                best = n.id();
            }
        }
        return best;
    }

    /** One step on reading {@code r}: drives the chair on, or stops it, and tells what happened. */
    void step(ChairReadings r, Pose pose, long now, Way way, Events events) {
        chair.observe(r);
        if (route == null) {
            chair.stop();
            return;
        }
        if (index >= route.size()) {
            events.arrived(now);
            return;
        }
        if (!way.mayDrive(route, standsOn())) {
            chair.stop();
            return;
        }
        if (index == 0) {
            Point first = map.node(route.get(0)).at();
            if (control.reached(pose, first.x(), first.y())) {
                index = 1;
                lastNode = route.get(0);
                edgeTo = -1;
                way.reached(null, route);
            } else {
                PoseController.Powers p = control.toPoint(pose, first.x(), first.y());
                chair.drive(p.left() * 0.5, p.right() * 0.5);
            }
            return;
        }
        int fromId = route.get(index - 1);
        int toId = route.get(index);
        Edge edge = map.edge(fromId, toId).orElse(null);
        if (edge == null) {
            events.broken(fromId, "the plan has no edge " + fromId + "-" + toId);
            return;
        }
        // On the graph's line, to the node itself, except straight on along a two-lane corridor:
        // there in the lane right of the line, through the node's lane point, where the traffic
        // agent lets a chair the other way pass in the other lane. Nowhere else: a chair kept 0.6 m
        // right of every line missed the markers once its heading had drifted 3 degrees in a spot
        // turn, and met a door's jamb 0.85 m off course (seed 156 of the soak); a lane is never
        // through a door, turns at most 30 degrees at a node, and has a floor marker of its own at
        // each lane point (HospitalMap.markers()).
        Point target = map.waypoint(fromId, toId, index + 1 < route.size() ? route.get(index + 1) : -1);
        if (control.reached(pose, target.x(), target.y())) {
            lastNode = toId;
            edgeTo = -1;
            index++;
            stoppedSinceMs = -1;
            facing = false;
            faced = false;
            way.reached(edge, route.subList(index - 1, route.size()));
            if (index >= route.size()) {
                events.arrived(now);
            }
            return;
        }
        if (edgeTo != toId && !way.mayGoOn(route, index)) {
            chair.stop(); // at the node it last reached: the next is not its turn yet
            return;
        }
        if (edge.door() != null && !way.mayEnter(edge, fromId, pose)) {
            chair.stop();
            return;
        }
        if (edgeTo != toId) {
            edgeTo = toId;
            way.setOff(standsOn()); // sets off along the edge: its body now takes both ends
        }
        PoseController.Powers p = control.toPoint(pose, target.x(), target.y());
        if (edge.door() != null && !p.stopped()) {
            // Into a doorway, square on: where the edge starts, the chair turns on the spot until it
            // faces the door's line, then drives straight through. Setting off with the controller's
            // 35 degrees of error it drove an arc, and from a lane's point 1 m from a door its
            // corner met the jamb (seed 10 of the generated maps' soak, the medium map).
            int before = index >= 2 ? route.get(index - 2) : -1;
            Point start = map.waypoint(before, fromId, toId);
            if (pose.distanceTo(start.x(), start.y()) < DOOR_SQUARE_M) {
                PoseController.Powers square = control.toHeading(pose, Math.atan2(target.y() - start.y(), target.x() - start.x()));
                if (!square.stopped()) {
                    p = square;
                }
            }
        }
        double bearing = Math.atan2(target.y() - pose.y(), target.x() - pose.x());
        if (facing) {
            PoseController.Powers face = control.toHeading(pose, bearing);
            if (!face.stopped() && now - facingSinceMs <= BLOCKED_AFTER_MS) {
                chair.drive(face.left(), face.right());
                return;
            }
            facing = false; // it faces its way (or has turned as long as it may): drives on, or is blocked
        }
        // The obstacle filter between here and the supervisor keeps the stop and slow zones (a turn on the
        // spot passes: it lets the chair turn away from what is ahead); here only what a stop means for the route.
        chair.drive(p.left(), p.right());
        double blocked = chair.blockedAt();
        if (!Double.isNaN(blocked)) {
            if (stoppedSinceMs < 0) {
                stoppedSinceMs = now;
                events.say(String.format(Locale.ROOT, "stops: something %.2f m ahead", blocked));
            } else if (now - stoppedSinceMs > BLOCKED_AFTER_MS) {
                stoppedSinceMs = -1;
                double off = Math.abs(Pose.normalize(bearing - pose.heading()));
                if (!faced && off > FACE_AFTER_STOP_RAD) {
                    faced = true;
                    facing = true;
                    facingSinceMs = now;
                    events.say(String.format(Locale.ROOT, "turns on the spot to face node %d (%.0f degrees off its way, stopped %d s)",
                            toId, Math.toDegrees(off), BLOCKED_AFTER_MS / 1000));
                    return;
                }
                events.blocked(fromId, toId);
            }
            return;
        }
        stoppedSinceMs = -1;
    }
}
