package io.concord.agents.control;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;
import io.concord.core.acl.AclMessage;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;

/** What the control agent's parts are tested on: a chair that records its commands, and a small map. */
final class Fakes {
    /**
     * The map of docs/hospital-map.md's example: a corridor (nodes 1 at (5, 2) and 3 at (8, 2))
     * and a room (node 2 at (5, 6.5)) behind a hinged door D1 centred at (5, 4).
     */
    static final HospitalMap SMALL = HospitalMap.parse("""
            {
              "format": "concord-hospital-map/1",
              "name": "small",
              "clearance": 0.4,
              "wallThickness": 0.15,
              "walls": [
                {"id": "outer", "path": [[0, 0], [10, 0], [10, 8], [0, 8], [0, 0]], "thickness": 0.25},
                {"id": "w1", "from": [0, 4], "to": [4.4, 4]},
                {"id": "w2", "from": [5.6, 4], "to": [10, 4]}
              ],
              "areas": [
                {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [10, 0], [10, 8], [0, 8]]},
                {"id": "corridor", "kind": "corridor", "name": "Corridor", "ward": "ward", "polygon": [[0, 0], [10, 0], [10, 4], [0, 4]]},
                {"id": "room", "kind": "room", "name": "Room 1", "ward": "ward", "polygon": [[0, 4], [10, 4], [10, 8], [0, 8]]}
              ],
              "doors": [
                {"id": "D1", "kind": "hinged", "from": [4.4, 4], "to": [5.6, 4], "hinge": "from", "swing": "left"}
              ],
              "nodes": [
                {"id": 1, "at": [5, 2], "name": "corridor, at the door"},
                {"id": 2, "at": [5, 6.5], "name": "room"},
                {"id": 3, "at": [8, 2]}
              ],
              "edges": [
                {"from": 1, "to": 2, "door": "D1"},
                {"from": 1, "to": 3}
              ]
            }
            """, "test");

    private Fakes() {
    }

    /** An outbox that records what is sent and asked, each question answered by the test through its future. */
    static class Recording implements Outbox {
        final List<AclMessage> sent = new ArrayList<>();
        final List<CompletableFuture<AclMessage>> answers = new ArrayList<>();
        final List<Long> timeouts = new ArrayList<>();

        @Override
        public void send(AclMessage m) {
            sent.add(m);
        }

        @Override
        public CompletableFuture<AclMessage> ask(AclMessage request, long timeoutMs) {
            sent.add(request);
            timeouts.add(timeoutMs);
            CompletableFuture<AclMessage> f = new CompletableFuture<>();
            answers.add(f);
            return f;
        }
    }

    /** A chair whose commands are recorded ("stop", or "drive L,R" in whole percent). */
    static final class Chair implements ChairDriver {
        final List<String> commands = new ArrayList<>();
        final List<double[]> powers = new ArrayList<>();
        ChairReadings latest;
        ChairListener listener;
        boolean online = true;

        @Override
        public String name() {
            return "chair1";
        }

        @Override
        public ChairLayout layout() {
            return ChairLayout.standard();
        }

        @Override
        public void drive(double l, double r) {
            commands.add(l == 0 && r == 0 ? "stop" : "drive " + Math.round(l) + "," + Math.round(r));
            powers.add(new double[] {l, r});
        }

        @Override
        public ChairReadings latest() {
            return latest;
        }

        @Override
        public boolean online() {
            return online;
        }

        @Override
        public void setListener(ChairListener listener) {
            this.listener = listener;
        }

        /** The board reports {@code r}. */
        void report(ChairReadings r) {
            latest = r;
            listener.onReadings(r);
        }

        /** The link goes down or comes back. */
        void link(boolean up) {
            online = up;
            listener.onOnline(up);
        }

        String last() {
            return commands.isEmpty() ? "nothing" : commands.get(commands.size() - 1);
        }

        double[] lastPowers() {
            return powers.get(powers.size() - 1);
        }
    }

    /**
     * A reading at {@code ms} on the chair's clock, the chair at {@code pose} (by odometry, no
     * marker), every range {@code clearM} but the front sonar's {@code frontM}.
     */
    static ChairReadings reading(long ms, Pose pose, double frontM, double clearM) {
        ChairLayout layout = ChairLayout.standard();
        double[] ranges = new double[layout.sensors().size()];
        Arrays.fill(ranges, clearM);
        ranges[layout.sensorIndex("front")] = frontM;
        return new ChairReadings(ms * 1_000_000, ms, 0, 0, ranges, false, 24, false, Set.of(), pose, null);
    }

    static ChairReadings clear(long ms, Pose pose) {
        return reading(ms, pose, 3.0, 3.0);
    }

    /** A reading at {@code ms} with the e-stop pressed or not, nothing near. */
    static ChairReadings estop(long ms, boolean pressed) {
        ChairLayout layout = ChairLayout.standard();
        double[] ranges = new double[layout.sensors().size()];
        Arrays.fill(ranges, 3.0);
        return new ChairReadings(ms * 1_000_000, ms, 0, 0, ranges, false, 24, pressed, Set.of(), new Pose(0, 0, 0), null);
    }
}
