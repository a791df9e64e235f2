package io.concord.sim;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Pose;
import io.concord.agents.control.ControlAgent;
import io.concord.agents.control.TaskView;
import io.concord.agents.door.DoorAgent;
import io.concord.agents.map.Door;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;
import io.concord.agents.map.Wall;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Done;
import io.concord.agents.proto.WheelchairMessage.Failed;
import io.concord.agents.proto.WheelchairMessage.TransportRequest;
import io.concord.console.ConsoleView;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.layers.Platform;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ServiceDescription;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;
import io.concord.sim.world.WorldDoor;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The hospital in the console: the map (walls, doors in their live state, route nodes), every
 * chair with its pose, planned route and task, the transports asked for and the chairs' bids; and
 * a form to ask for a transport, which the front desk agent sends to the Medical agent of the
 * yellow pages as a FIPA REQUEST (so it works with the Medical agent in another JVM).
 */
public final class HospitalView implements ConsoleView {
    private final HospitalWorld world;
    private final Hospital hospital;
    private final FrontDesk desk;
    private final ObjectMapper json = new ObjectMapper();
    private final double[] bounds;
    /** A serial chair's pose at the last snapshot (board time in ns, x, y), for its speed; and the speed then. Loop thread. */
    private final Map<String, double[]> serialPoses = new java.util.HashMap<>();
    private final Map<String, String> serialSpeeds = new java.util.HashMap<>();

    /** The agent behind the form: asks the Medical agent, keeps what it answered. */
    public static final class FrontDesk extends Agent {
        /** A transport asked for here. */
        record Asked(String id, int from, int to, double priority, String state, String detail) {
        }

        private final List<Asked> asked = new ArrayList<>();
        /** desk id -> where the request came from (the console's client), for the audit trail. */
        private final Map<String, String> origins = new java.util.HashMap<>();
        /** desk id -> the operator behind the request (the console's operator key's name), for the audit trail. */
        private final Map<String, String> operators = new java.util.HashMap<>();
        /** A cancel asked here: its conversation, the transport, where it stands, what the Medical agent said. */
        record Cancel(String id, String task, String state, String detail) {
        }

        private final List<Cancel> cancels = new ArrayList<>();
        /** The Medical agent's last audit answer: its transports, newest first. */
        private volatile com.fasterxml.jackson.databind.JsonNode audit;
        /** The transport whose story was asked for, and the story as the Medical agent answered it. */
        private volatile String storyOf;
        private volatile com.fasterxml.jackson.databind.JsonNode story;
        private long auditDueMs;
        private long queries;
        private static final long AUDIT_MS = 2_000;
        private static final com.fasterxml.jackson.databind.ObjectMapper JSON = new com.fasterxml.jackson.databind.ObjectMapper();

        @Override
        protected void setup() {
            Inbox.each(this, MessageTemplate.matchPerformative(Performative.INFORM).and(MessageTemplate.matchConversationId("audit")), this::audited);
            Inbox.each(this, MessageTemplate.not(MessageTemplate.matchConversationId("audit"))
                    .and(m -> m.getConversationId() != null && m.getConversationId().startsWith("cancel-")), this::cancelAnswered);
            Inbox.each(this, MessageTemplate.not(MessageTemplate.matchConversationId("audit"))
                    .and(m -> m.getConversationId() == null || !m.getConversationId().startsWith("cancel-")), this::answered);
        }

        /** Asks the Medical agent for its audit trail, at most every two seconds (while the view is drawn). Loop thread. */
        void refreshAudit() {
            long now = currentTimeMillis();
            if (now < auditDueMs) {
                return;
            }
            auditDueMs = now + AUDIT_MS;
            query("audit");
            if (storyOf != null) {
                query("audit " + storyOf);
            }
        }

        /** The Medical agent in this agent's copy of the yellow pages, or null. */
        private AID medical() {
            List<AgentEntry> medical = Platform.of(this).searchCopy(ServiceDescription.ofType(Services.MEDICAL));
            return medical.isEmpty() ? null : medical.get(0).aid();
        }

        private boolean query(String what) {
            AID medical = medical();
            if (medical == null) {
                return false;
            }
            AclMessage q = new AclMessage(Performative.QUERY_REF);
            q.addReceiver(medical);
            q.setOntology(Services.ONTOLOGY);
            q.setConversationId("audit");
            q.setReplyWith("audit-" + (++queries));
            q.setContent(what);
            send(q);
            return true;
        }

        /** The story of one transport: asked now, shown when the Medical agent answers. Loop thread. */
        String askStory(String task) {
            if (!task.matches("T\\d{1,9}")) {
                throw new IllegalArgumentException("a transport is named by the Medical agent's id, T and a number; got '" + task + "'");
            }
            storyOf = task;
            story = null;
            if (!query("audit " + task)) {
                throw new IllegalArgumentException("no Medical agent in the yellow pages yet");
            }
            return "asked the Medical agent for the story of " + task;
        }

        private void audited(AclMessage m) {
            try {
                com.fasterxml.jackson.databind.JsonNode n = JSON.readTree(m.getContent());
                com.fasterxml.jackson.databind.JsonNode ts = n.path("transports");
                if (n.has("task")) {
                    // One transport's story (or that the Medical agent has none of that id).
                    if (n.path("task").asText().equals(storyOf)) {
                        story = n.path("unknown").asBoolean() ? n : ts.get(0);
                    }
                } else {
                    audit = ts;
                }
            } catch (java.io.IOException | RuntimeException e) {
                // an answer that is not the audit's JSON: nothing to show
            }
        }

        /** The Medical agent's last audit answer (its transports, newest first), or {@code null}. */
        com.fasterxml.jackson.databind.JsonNode audit() {
            return audit;
        }

        /** The story last asked for, as answered, or {@code null}. */
        com.fasterxml.jackson.databind.JsonNode story() {
            return story;
        }

        /** Where the desk's request came from, or empty. */
        String origin(String deskId) {
            return origins.getOrDefault(deskId, "");
        }

        /** The operator behind the desk's request, or empty. */
        String operator(String deskId) {
            return operators.getOrDefault(deskId, "");
        }

        /**
         * Asks the Medical agent to withdraw a transport the desk asked for ({@code cancel-request});
         * its answer shows in the table of cancels. Loop thread.
         */
        String cancel(String task, String reason) {
            return cancel(task, reason, null);
        }

        /**
         * As {@link #cancel(String, String)}, with an operator's signed order ({@code cancel} of
         * that task), with which the Medical agent withdraws any transport, not only this desk's.
         */
        String cancel(String task, String reason, String order) {
            AID medical = medical();
            if (medical == null) {
                throw new IllegalArgumentException("no Medical agent in the yellow pages yet");
            }
            String id = "cancel-" + (cancels.size() + 1);
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(medical);
            m.setConversationId(id);
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(new WheelchairMessage.CancelRequest(task, reason, order).encode());
            send(m);
            cancels.add(new Cancel(id, task, "asked", "to " + medical.localName()));
            if (cancels.size() > 200) {
                cancels.remove(0);
            }
            auditDueMs = 0;
            return "asked " + medical.localName() + " to withdraw " + task + " (" + id + ")";
        }

        /** The Medical agent's AGREE (withdrawn) or REFUSE (why not) to a cancel asked here. */
        private void cancelAnswered(AclMessage m) {
            for (int i = 0; i < cancels.size(); i++) {
                Cancel c = cancels.get(i);
                if (c.id().equals(m.getConversationId())) {
                    String state = m.getPerformative() == Performative.AGREE ? "withdrawn"
                            : m.getPerformative() == Performative.REFUSE ? "refused" : c.state();
                    String why = m.getPerformative() == Performative.REFUSE ? WheelchairMessage.reasonOf(m) : "by " + m.getSender().localName();
                    cancels.set(i, new Cancel(c.id(), c.task(), state, why == null ? String.valueOf(m.getContent()) : why));
                    auditDueMs = 0;
                }
            }
        }

        /** The Medical agent's AGREE, INFORM, FAILURE or REFUSE to one of the desk's requests. */
        private void answered(AclMessage m) {
            for (int i = 0; i < asked.size(); i++) {
                Asked a = asked.get(i);
                if (!a.id().equals(m.getConversationId())) {
                    continue;
                }
                String state = switch (m.getPerformative()) {
                    case AGREE -> "agreed";
                    case INFORM -> "done";
                    case FAILURE -> "failed";
                    case REFUSE -> "refused";
                    default -> a.state();
                };
                String detail = a.detail();
                try {
                    WheelchairMessage w = WheelchairMessage.decode(m);
                    String chair = w instanceof Done d ? d.chair() : w instanceof Failed f ? f.chair() : null;
                    // The Medical agent's own id for it, as its log says it (T2...), beside the desk's.
                    String task = w instanceof Done d ? d.task() : w instanceof Failed f ? f.task() : null;
                    String reason = w instanceof WheelchairMessage.Reasoned r ? r.reason() : null;
                    boolean byChair = chair != null && !chair.isEmpty();
                    if (w instanceof Failed f && f.reason().startsWith("withdrawn")) {
                        state = "withdrawn";   // called off (at this console or elsewhere), not a chair's failure
                    }
                    // Done: who did it. Failed or withdrawn: why, and whose it was.
                    detail = w instanceof Done ? (byChair ? "by " + chair : detail)
                            : reason != null ? reason + (byChair ? "; it was " + chair + "'s" : "") : byChair ? "by " + chair : detail;
                    if (task != null && !task.isEmpty()) {
                        detail = task + ": " + detail;
                    }
                } catch (IllegalArgumentException e) {
                    detail = "an answer that is not content: " + m.getContent();
                }
                asked.set(i, new Asked(a.id(), a.from(), a.to(), a.priority(), state, detail));
            }
        }

        /** Sends the request; returns what to tell the user. Loop thread. */
        String ask(int from, int to, double priority, double unloadS) {
            return ask(from, to, priority, unloadS, "");
        }

        /** As {@link #ask(int, int, double, double)}, noting where the request came from (the console's client). */
        String ask(int from, int to, double priority, double unloadS, String origin) {
            return ask(from, to, priority, unloadS, origin, "");
        }

        /** As {@link #ask(int, int, double, double, String)}, noting the operator behind it too (the console's operator key's name). */
        String ask(int from, int to, double priority, double unloadS, String origin, String operator) {
            AID medical = medical();
            if (medical == null) {
                throw new IllegalArgumentException("no Medical agent in the yellow pages yet");
            }
            String id = "desk-" + (asked.size() + 1);
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(medical);
            m.setConversationId(id);
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(new TransportRequest(from, to, priority, unloadS).encode());
            send(m);
            asked.add(new Asked(id, from, to, priority, "asked", "to " + medical.localName()));
            origins.put(id, origin);
            operators.put(id, operator);
            auditDueMs = 0;   // the new transport shows in the audit at the next snapshot
            if (asked.size() > 200) {
                asked.remove(0);
            }
            return "asked " + medical.localName() + " for a transport from node " + from + " to node " + to + " (" + id + ")";
        }
    }

    /** The view of a ward; {@code desk} asks for transports, or {@code null} for a view without the form's desk (a recording). */
    public HospitalView(HospitalWorld world, Hospital hospital, FrontDesk desk) {
        this.world = world;
        this.hospital = hospital;
        this.desk = desk;
        HospitalMap map = world.map();
        double x0 = Double.MAX_VALUE;
        double y0 = Double.MAX_VALUE;
        double x1 = -Double.MAX_VALUE;
        double y1 = -Double.MAX_VALUE;
        for (Wall w : map.walls()) {
            x0 = Math.min(x0, Math.min(w.from().x(), w.to().x()));
            y0 = Math.min(y0, Math.min(w.from().y(), w.to().y()));
            x1 = Math.max(x1, Math.max(w.from().x(), w.to().x()));
            y1 = Math.max(y1, Math.max(w.from().y(), w.to().y()));
        }
        // Below the floor, a strip for the legend.
        this.bounds = new double[] {x0 - 1, y0 - 1 - LEGEND_M, x1 + 1, y1 + 1};
    }

    @Override
    public String id() {
        return "hospital";
    }

    @Override
    public String title() {
        return "Hospital";
    }

    @Override
    public List<String> actions() {
        return List.of("transport", "resume", "story", "cancel", "stop-all");
    }

    @Override
    public String act(String action, Map<String, String> p) {
        if (action.equals("resume")) {
            return resume(p.getOrDefault("chair", "").trim());
        }
        if (action.equals("story")) {
            if (desk == null) {
                throw new IllegalArgumentException("this view has no front desk (a recording of a run): no story to ask for");
            }
            return desk.askStory(p.getOrDefault("task", "").trim());
        }
        if (action.equals("cancel")) {
            return cancel(p.getOrDefault("task", "").trim(), p.getOrDefault("reason", "").trim(), who(p));
        }
        if (action.equals("stop-all")) {
            return stopAll(who(p));
        }
        HospitalMap map = world.map();
        int from = map.nodeNamed(p.getOrDefault("from", ""));
        int to = map.nodeNamed(p.getOrDefault("to", ""));
        double priority = number(p, "priority", 0);
        double unload = number(p, "unload", 60);
        if (priority < 0 || priority > 3 || unload < 0 || unload > 3_600) {
            throw new IllegalArgumentException("priority is 0 to 3 and unload 0 to 3600 s");
        }
        if (desk == null) {
            throw new IllegalArgumentException("this view has no front desk (a recording of a run): nothing to ask");
        }
        return desk.ask(from, to, priority, unload, p.getOrDefault(io.concord.console.ConsoleView.CLIENT, ""), hospital.operatorKey().name());
    }

    /** Who acts: the console's operator (its operator key's name) and the browser's address. */
    private String who(Map<String, String> p) {
        String client = p.getOrDefault(io.concord.console.ConsoleView.CLIENT, "");
        return "operator " + hospital.operatorKey().name() + (client.isEmpty() ? "" : " at console client " + client);
    }

    /**
     * Withdraws a transport, keeping the rule that a patient on board is never left: refused at
     * once if a chair of this ward has its patient on board (the Medical agent refuses it too,
     * whatever the console says); otherwise the front desk asks the Medical agent, which answers
     * in the table of cancels and ends the transport in the audit trail.
     */
    private String cancel(String task, String reason, String who) {
        if (!task.matches("T\\d{1,9}")) {
            throw new IllegalArgumentException("a transport is named by the Medical agent's id, T and a number (the audit trail's task column); got '"
                    + task + "'");
        }
        for (ControlAgent ctl : hospital.controls()) {
            for (TaskView t : ctl.tasks()) {
                if (t.id().equals(task) && t.state().patientOnBoard()) {
                    throw new IllegalArgumentException(task + " is not cancelled: its patient is on board " + ctl.supervisor().name() + " ("
                            + t.state().name().toLowerCase(Locale.ROOT).replace('_', '-') + "), which drives on to the drop-off at node " + t.to()
                            + "; a transport with its patient on board is never withdrawn");
                }
            }
        }
        if (desk == null) {
            throw new IllegalArgumentException("this view has no front desk (a recording of a run): nothing to cancel");
        }
        // Signed with the console's operator key: the Medical agent withdraws the staff's transports too (the demo's --tasks).
        String order = hospital.operatorKey().sign("cancel", task, desk.runtime().clock().epochMillis()).encode();
        return desk.cancel(task, (reason.isEmpty() ? "cancelled at the console" : reason) + " (" + who + ")", order);
    }

    /**
     * Stops every chair of the ward: each supervisor holds it as an operator's stop, which only an
     * operator's Resume releases (the agents never resume it by themselves).
     */
    private String stopAll(String who) {
        List<String> stopped = new ArrayList<>();
        for (ControlAgent ctl : hospital.controls()) {
            var sup = ctl.supervisor();
            if (ctl.runtime().inLoop()) {
                sup.holdByOperator("stop all by " + who);
            } else {
                ctl.runtime().execute(() -> sup.holdByOperator("stop all by " + who));
            }
            stopped.add(sup.name());
        }
        if (stopped.isEmpty()) {
            throw new IllegalArgumentException("no chair in this ward to stop");
        }
        return "stopped " + stopped.size() + (stopped.size() == 1 ? " chair" : " chairs") + " (" + String.join(", ", stopped)
                + "): each stays held until an operator resumes it";
    }

    /** An operator's decision that a held chair may drive again (its supervisor re-arms it; docs/chair-safety.md). */
    private String resume(String chair) {
        ControlAgent ctl = hospital.control(chair);
        if (ctl == null) {
            throw new IllegalArgumentException("no chair named '" + chair + "'; chairs: "
                    + String.join(", ", hospital.controls().stream().map(c -> c.supervisor().name()).toList()));
        }
        if (ctl.supervisor().state() == io.concord.agents.chair.ChairSupervisor.State.ARMED) {
            throw new IllegalArgumentException(chair + " is not held: it is armed and drives as its tasks ask; nothing to resume");
        }
        // The console signs with the operator key it was started with; the control agent checks it.
        var f = ctl.resume(hospital.operatorKey().sign("resume", chair, ctl.runtime().clock().epochMillis()));
        if (!f.isDone()) {
            return "asked " + chair + " to resume";
        }
        String why = f.join();
        if (why != null) {
            throw new IllegalArgumentException(chair + " cannot resume: " + why);
        }
        return chair + " resumes: it re-arms, then drives on";
    }

    /**
     * The traffic agent's reservations: a ring round each node someone holds (solid: the chair
     * whose turn it is there; dashed, smaller: each chair queued after it), titled with the queue;
     * at a node chairs pass in lanes, a ring round each lane's point ({@code reserved-N-lane-L}).
     */
    private void reservations(ArrayNode shapes) {
        if (hospital.traffic() == null) {
            return;
        }
        HospitalMap map = world.map();
        Map<Integer, List<List<String>>> lanes = hospital.traffic().lanes();
        hospital.traffic().holders().forEach((node, queue) -> {
            if (!map.hasNode(node) || queue.isEmpty()) {
                return;
            }
            if (lanes.containsKey(node) && map.laned(node)) {
                for (int lane = 0; lane < 2; lane++) {
                    if (!lanes.get(node).get(lane).isEmpty()) {
                        rings(shapes, map.lanePoint(node, lane), "node " + node + ", lane " + lane, node + "-lane-" + lane,
                                lanes.get(node).get(lane));
                    }
                }
            } else {
                rings(shapes, map.node(node).at(), "node " + node, Integer.toString(node), queue);
            }
        });
    }

    /** How far a point is from the nearest of {@code labels}, counting a label's width twice its height. */
    private static double clearOfLabels(List<Point> labels, Point p) {
        double best = Double.MAX_VALUE;
        for (Point q : labels) {
            best = Math.min(best, Math.hypot((p.x() - q.x()) / 2, p.y() - q.y()));
        }
        return best;
    }

    /** The legend's strip under the floor, in metres. */
    private static final double LEGEND_M = 1.6;

    /** What the marks mean, in a row under the floor: doors by state, a chair, its route, its reservations. */
    private void legend(ArrayNode shapes) {
        double y = bounds[1] + 0.9;
        double x = bounds[0] + 1;
        String[][] doors = {{"closed", "#c0392b"}, {"moving", "#e08e0b"}, {"open", "#27ae60"}, {"failed", "#7f8c8d"}};
        for (String[] d : doors) {
            line(shapes, d[1], 0.35, x, y, x + 0.9, y);
            x = legendText(shapes, x + 1.35, y, "door " + d[0], "legend-door-" + d[0]);
        }
        shapes.addObject().put("type", "circle").put("x", x + 0.45).put("y", y).put("r", 0.45).put("color", colour("chair1"))
                .put("stroke", "#ffffff");
        x = legendText(shapes, x + 1.1, y, "a chair, its colour", "legend-chair");
        ObjectNode route = shapes.addObject().put("type", "line").put("color", colour("chair1")).put("width", 0.12).put("dash", "0.4 0.3");
        route.putArray("points").add(x).add(y).add(x + 1.2).add(y);
        x = legendText(shapes, x + 1.4, y, "its route", "legend-route");
        shapes.addObject().put("type", "circle").put("x", x + 0.7).put("y", y).put("r", 0.7).put("color", "none").put("stroke", colour("chair1"))
                .put("strokeWidth", 0.14);
        x = legendText(shapes, x + 1.6, y, "its turn (node or lane)", "legend-turn");
        shapes.addObject().put("type", "circle").put("x", x + 0.5).put("y", y).put("r", 0.45).put("color", "none").put("stroke", colour("chair1"))
                .put("strokeWidth", 0.07).put("dash", "0.15 0.12");
        x = legendText(shapes, x + 1.2, y, "queued after it", "legend-queued");
        shapes.addObject().put("type", "circle").put("x", x + 0.45).put("y", y).put("r", 0.45).put("color", colour("chair1"))
                .put("stroke", "#c0392b").put("strokeWidth", 0.16);
        legendText(shapes, x + 1.1, y, "held or lost", "legend-held");
    }

    /** A legend's words, starting at {@code x}; returns where the next item may start. */
    private static double legendText(ArrayNode shapes, double x, double y, String text, String id) {
        double w = 0.25 * text.length();
        shapes.addObject().put("type", "text").put("x", x + w / 2).put("y", y - 0.18).put("size", 0.5).put("color", "#4a5160")
                .put("text", text).put("id", id);
        return x + w + 0.8;
    }

    /**
     * A chair's colour, the same for its body, its route and its reservations: the picture's
     * palette ({@link io.concord.sim.render.HospitalPicture#chairColour}) by the chair's number.
     */
    static String colour(String chair) {
        int n = 0;
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(\\d+)$").matcher(chair);
        if (m.find()) {
            n = Integer.parseInt(m.group(1)) - 1;
        }
        return io.concord.sim.render.HospitalPicture.chairColour(n);
    }


    /** A queue's rings at a point (a node, or a lane's point at a node with lanes), titled with the queue. */
    private static void rings(ArrayNode shapes, Point at, String where, String id, List<String> queue) {
        List<String> names = queue.stream().map(a -> a.replaceFirst("@.*", "").replaceFirst("^control-", "")).toList();
        String title = where + ": " + names.get(0) + "'s turn" + (names.size() > 1 ? "; queued: "
                + String.join(", ", names.subList(1, names.size())) : "");
        for (int k = 0; k < names.size(); k++) {
            ObjectNode ring = shapes.addObject().put("type", "circle").put("x", at.x()).put("y", at.y())
                    .put("r", k == 0 ? 0.7 : Math.max(0.3, 0.55 - 0.1 * k)).put("color", "none").put("stroke", colour(names.get(k)))
                    .put("strokeWidth", k == 0 ? 0.14 : 0.07).put("title", title);
            if (k > 0) {
                ring.put("dash", "0.15 0.12");
            } else {
                ring.put("id", "reserved-" + id);
                ring.putObject("data").put("queue", String.join(",", names));
            }
        }
    }

    private static double number(Map<String, String> p, String k, double dflt) {
        String v = p.getOrDefault(k, "").trim();
        try {
            return v.isEmpty() ? dflt : Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(k + " must be a number, got '" + v + "'");
        }
    }

    @Override
    public String snapshot() {
        HospitalMap map = world.map();
        ObjectNode o = json.createObjectNode();
        ArrayNode b = o.putArray("bounds");
        for (double d : bounds) {
            b.add(d);
        }
        o.put("worldTimeS", world.worldTimeNs() / 1e9);
        ArrayNode shapes = o.putArray("shapes");
        for (Wall w : map.walls()) {
            line(shapes, "#3b4252", Math.max(0.1, w.thicknessM()), w.from().x(), w.from().y(), w.to().x(), w.to().y());
        }
        List<Point> labels = new ArrayList<>();
        // The rooms', corridors' and halls' names, near the top of each (the nodes' numbers are at their centres).
        for (io.concord.agents.map.Area a : map.areas()) {
            if (a.kind() == io.concord.agents.map.Area.Kind.WARD || a.name() == null) {
                continue;
            }
            double ax0 = Double.MAX_VALUE;
            double ax1 = -Double.MAX_VALUE;
            double ay1 = -Double.MAX_VALUE;
            for (Point q : a.polygon()) {
                ax0 = Math.min(ax0, q.x());
                ax1 = Math.max(ax1, q.x());
                ay1 = Math.max(ay1, q.y());
            }
            shapes.addObject().put("type", "text").put("x", (ax0 + ax1) / 2).put("y", ay1 - 0.7).put("size", 0.5).put("color", "#9aa3b2")
                    .put("text", a.name()).put("id", "label-area-" + a.id());
            labels.add(new Point((ax0 + ax1) / 2, ay1 - 0.7));
        }
        for (Node n : map.nodes()) {
            shapes.addObject().put("type", "circle").put("x", n.at().x()).put("y", n.at().y()).put("r", 0.22).put("color", "#c8cfdb")
                    .put("title", "node " + n.id() + (n.name() == null ? "" : ": " + n.name()));
            labels.add(new Point(n.at().x(), n.at().y() - 0.6));
            shapes.addObject().put("type", "text").put("x", n.at().x()).put("y", n.at().y() - 0.6).put("size", 0.45)
                    .put("color", "#7b8494").put("text", Integer.toString(n.id()));
        }
        for (WorldDoor wd : world.doors()) {
            Door d = wd.spec();
            DoorAgent a = hospital.door(wd.id());
            String state = a == null ? "unknown" : a.state().name().toLowerCase(Locale.ROOT);
            String color = switch (state) {
                case "closed" -> "#c0392b";
                case "opening", "closing" -> "#e08e0b";
                case "open" -> "#27ae60";
                default -> "#7f8c8d";
            };
            ObjectNode s = line(shapes, color, 0.35, d.from().x(), d.from().y(), d.to().x(), d.to().y());
            s.put("id", "door-" + wd.id()).put("title", "door " + wd.id() + ": " + state);
            // Its name beside the opening: of the four places by either jamb on either side of the
            // wall, the one farthest from the other labels (nodes' numbers, rooms' names).
            double nx = -(d.to().y() - d.from().y()) / d.width();
            double ny = (d.to().x() - d.from().x()) / d.width();
            double ux = (d.to().x() - d.from().x()) / d.width();
            double uy = (d.to().y() - d.from().y()) / d.width();
            Point label = null;
            double room = -1;
            for (int side = -1; side <= 1; side += 2) {
                for (int end = -1; end <= 1; end += 2) {
                    Point q = new Point(d.centre().x() + side * 0.45 * nx + end * (d.width() / 2 + 0.3) * ux,
                            d.centre().y() + side * 0.45 * ny + end * (d.width() / 2 + 0.3) * uy);
                    double free = clearOfLabels(labels, q);
                    if (free > room + 1e-9) {
                        room = free;
                        label = q;
                    }
                }
            }
            shapes.addObject().put("type", "text").put("x", label.x()).put("y", label.y()).put("size", 0.45)
                    .put("color", color).put("text", wd.id()).put("id", "label-door-" + wd.id());
            s.putObject("data").put("state", state).put("open", String.format(Locale.ROOT, "%.2f", wd.openFraction()));
        }
        reservations(shapes);
        legend(shapes);
        ArrayNode chairs = json.createArrayNode();
        ArrayNode tasks = json.createArrayNode();
        for (SimChair c : world.chairs()) {
            ControlAgent ctl = hospital.control(c.name());
            Pose p = c.truePose();
            if (ctl != null) {
                List<Integer> route = ctl.route();
                if (route != null && !route.isEmpty()) {
                    ObjectNode path = shapes.addObject().put("type", "line").put("color", colour(c.name())).put("width", 0.12).put("dash", "0.4 0.3");
                    ArrayNode pts = path.putArray("points");
                    pts.add(p.x()).add(p.y());
                    // What is left of the route: from the leg the chair is on.
                    List<Integer> left = route.stream().filter(map::hasNode).toList();
                    int from = 0;
                    double best = Double.MAX_VALUE;
                    for (int i = 0; i + 1 < left.size(); i++) {
                        double d = toSegment(p, map.node(left.get(i)).at(), map.node(left.get(i + 1)).at());
                        if (d < best - 1e-9) {
                            best = d;
                            from = i + 1;
                        }
                    }
                    for (int i = from; i < left.size(); i++) {
                        pts.add(map.node(left.get(i)).at().x()).add(map.node(left.get(i)).at().y());
                    }
                    path.put("id", "route-" + c.name());
                }
            }
            drawChair(shapes, c.name(), p, ctl, false);
            TaskView current = null;
            if (ctl != null) {
                for (TaskView t : ctl.tasks()) {
                    if (current == null && t.state().ordinal() >= TaskView.State.QUEUED.ordinal() && t.state().ordinal() <= TaskView.State.UNLOADING.ordinal()) {
                        current = t;
                    }
                    tasks.add(bidRow(c.name(), t));
                }
            }
            chairs.add(json.createArrayNode().add(c.name()).add(poseText(p))
                    .add(String.format(Locale.ROOT, "%.2f m/s", Math.abs(c.forwardSpeed()) < 0.005 ? 0.0 : c.forwardSpeed()))
                    .add(battery(ctl))
                    .add(current == null ? "idle" : current.id() + " " + current.state().name().toLowerCase(Locale.ROOT))
                    .add(ctl == null ? "" : safety(ctl)));
        }
        // Chairs that are not in this world: a real or emulated chair on its serial port.
        for (ControlAgent ctl : hospital.controls()) {
            String name = ctl.supervisor().name();
            if (world.chairs().stream().anyMatch(c -> c.name().equals(name))) {
                continue;
            }
            Pose p = ctl.pose();
            String task = "idle";
            for (TaskView t : ctl.tasks()) {
                if (task.equals("idle") && t.state().ordinal() >= TaskView.State.QUEUED.ordinal()
                        && t.state().ordinal() <= TaskView.State.UNLOADING.ordinal()) {
                    task = t.id() + " " + t.state().name().toLowerCase(Locale.ROOT);
                }
                tasks.add(bidRow(name, t));
            }
            String speed = "";
            var r = ctl.supervisor().latest();
            if (r != null) {
                // The wheels' own travel, from one snapshot to the next, over the board's clock: the
                // odometry integrated from the encoders, not the located pose a floor marker moves.
                Pose odo = r.odometry();
                double[] before = serialPoses.put(name, new double[] {r.timeNs(), odo.x(), odo.y()});
                if (before != null && r.timeNs() > before[0]) {
                    double v = Math.hypot(odo.x() - before[1], odo.y() - before[2]) / ((r.timeNs() - before[0]) / 1e9);
                    speed = String.format(Locale.ROOT, "%.2f m/s", v < 0.005 ? 0.0 : v);
                    serialSpeeds.put(name, speed);
                } else {
                    speed = serialSpeeds.getOrDefault(name, "");
                }
            }
            if (p != null) {
                drawChair(shapes, name, p, ctl, true);
            }
            chairs.add(json.createArrayNode().add(name + " (serial)")
                    .add(p == null ? "unknown" : poseText(p)).add(speed)
                    .add(battery(ctl)).add(task).add(safety(ctl)));
        }
        ArrayNode tables = o.putArray("tables");
        table(tables, "chairs", "Chairs at " + String.format(Locale.ROOT, "t = %.0f s", world.worldTimeNs() / 1e9),
                List.of("chair", "pose", "speed", "battery", "task", "safety"), chairs);
        ArrayNode asked = json.createArrayNode();
        for (FrontDesk.Asked a : desk == null ? List.<FrontDesk.Asked>of() : List.copyOf(desk.asked)) {
            asked.add(json.createArrayNode().add(a.id()).add(a.from() + " → " + a.to()).add(a.state()).add(a.detail()));
        }
        table(tables, "transports", "Transports asked here", List.of("id", "from → to", "state", "detail"), asked);
        ArrayNode cancelled = json.createArrayNode();
        for (FrontDesk.Cancel c : desk == null ? List.<FrontDesk.Cancel>of() : List.copyOf(desk.cancels)) {
            cancelled.add(json.createArrayNode().add(c.id()).add(c.task()).add(c.state()).add(c.detail()));
        }
        table(tables, "cancels", "Cancels asked here", List.of("id", "task", "state", "detail"), cancelled);
        table(tables, "bids", "The chairs' tasks and bids (the Medical agent's auctions)", List.of("chair", "task", "from → to", "state", "cost", "reason"), tasks);
        if (desk != null) {
            desk.refreshAudit();
            auditTable(tables);
        }
        ArrayNode forms = o.putArray("forms");
        ObjectNode f = forms.addObject().put("title", "Ask for a transport").put("action", "transport").put("button", "Ask the Medical agent");
        ArrayNode fields = f.putArray("fields");
        fields.addObject().put("name", "from").put("label", "from node or room").put("value", "3");
        fields.addObject().put("name", "to").put("label", "to node or room").put("value", "9");
        fields.addObject().put("name", "priority").put("label", "priority (0, 1.5, 3)").put("value", "3");
        fields.addObject().put("name", "unload").put("label", "load/unload s").put("value", "30");
        ObjectNode r = forms.addObject().put("title", "Resume a held chair (after an e-stop, a reboot, a refusal)").put("action", "resume")
                .put("button", "Resume");
        r.putArray("fields").addObject().put("name", "chair").put("label", "chair").put("value",
                hospital.controls().isEmpty() ? "chair1" : hospital.controls().get(0).supervisor().name());
        ObjectNode c = forms.addObject().put("title", "Cancel a transport (not once its patient is on board)").put("action", "cancel")
                .put("button", "Cancel the transport");
        ArrayNode cf = c.putArray("fields");
        cf.addObject().put("name", "task").put("label", "transport (T1...)").put("value", "T1");
        cf.addObject().put("name", "reason").put("label", "why").put("value", "");
        forms.addObject().put("title", "Stop every chair (each stays held until an operator resumes it)").put("action", "stop-all")
                .put("button", "Stop all chairs").putArray("fields");
        return o.toString();
    }

    private static final java.time.format.DateTimeFormatter CLOCK = java.time.format.DateTimeFormatter.ofPattern("HH:mm:ss")
            .withZone(java.time.ZoneOffset.UTC);

    private static String clock(long ms) {
        return ms <= 0 ? "" : CLOCK.format(java.time.Instant.ofEpochMilli(ms));
    }

    /**
     * The Medical agent's audit trail (who asked, from where, when; the chair; when each phase
     * began; how it ended and why), a row a transport, newest first; a click on a row asks for its
     * story, shown in a table of its own. Times are the platform's clock, UTC; the CSV the page
     * exports has them in full (ISO 8601).
     */
    private void auditTable(ArrayNode tables) {
        ArrayNode rows = json.createArrayNode();
        ArrayNode csv = json.createArrayNode();
        com.fasterxml.jackson.databind.JsonNode a = desk.audit;
        if (a != null) {
            for (com.fasterxml.jackson.databind.JsonNode t : a) {
                String by = t.path("askedBy").asText();
                String conv = t.path("conversation").asText();
                String origin = desk.origin(conv);
                String operator = desk.operator(conv);
                String asker = by + (conv.isEmpty() ? "" : " (" + conv + ")") + (operator.isEmpty() ? "" : ", operator " + operator)
                        + (origin.isEmpty() ? "" : ", console client " + origin);
                ArrayNode r = rows.addArray().add(t.path("task").asText()).add(asker).add(clock(t.path("askedAtMs").asLong()))
                        .add(t.path("from").asInt() + " → " + t.path("to").asInt()).add(t.path("chair").asText());
                ArrayNode c = csv.addArray().add(t.path("task").asText()).add(by).add(conv).add(origin).add(iso(t.path("askedAtMs").asLong()))
                        .add(t.path("from").asInt()).add(t.path("to").asInt()).add(t.path("priority").asDouble()).add(t.path("chair").asText())
                        .add(t.path("auctions").asInt());
                for (String ph : io.concord.agents.medical.TransportAudit.PHASES) {
                    long at = t.path("phases").path(ph).asLong(0);
                    r.add(clock(at));
                    c.add(iso(at));
                }
                long end = t.path("endedAtMs").asLong(-1);
                r.add(clock(end)).add(t.path("outcome").asText()).add(t.path("reason").asText());
                c.add(iso(end)).add(t.path("outcome").asText()).add(t.path("reason").asText()).add(operator);
            }
        }
        ObjectNode t = table(tables, "audit", "Audit trail (the Medical agent's; click a transport for its story)",
                List.of("task", "asked by", "asked at", "from → to", "chair", "awarded", "to pick-up", "loading", "to drop-off", "unloading",
                        "ended", "outcome", "reason"), rows);
        t.putObject("click").put("action", "story").put("param", "task").put("column", 0);
        t.put("wide", true);
        ObjectNode x = t.putObject("csv");
        ArrayNode cols = x.putArray("columns");
        List.of("task", "asked_by", "conversation", "origin", "asked_at", "from", "to", "priority", "chair", "auctions", "awarded",
                "to_pickup", "loading", "to_dropoff", "unloading", "ended", "outcome", "reason", "operator").forEach(cols::add);
        x.set("rows", csv);
        com.fasterxml.jackson.databind.JsonNode st = desk.story;
        if (desk.storyOf != null) {
            ArrayNode lines = json.createArrayNode();
            if (st != null) {
                for (com.fasterxml.jackson.databind.JsonNode l : st.path("story")) {
                    lines.addArray().add(clock(l.path("atMs").asLong())).add(l.path("text").asText());
                }
            }
            table(tables, "story", "The story of " + desk.storyOf + (st == null ? " (asked)" : st.path("unknown").asBoolean()
                    ? ": the Medical agent has no transport of that id" : st.path("storyCut").asInt() > 0
                    ? " (" + st.path("storyCut").asInt() + " later lines left out)" : ""), List.of("time", "what happened"), lines)
                    .put("wide", true);
        }
    }

    private static String iso(long ms) {
        return ms <= 0 ? "" : java.time.Instant.ofEpochMilli(ms).toString();
    }

    /**
     * A chair on the map, simulated or serial alike: its body in its colour, its heading, its name,
     * and a red ring while its supervisor holds it (e-stop, trip, reboot, refusal, an operator's
     * stop) or has lost it, with why in its title.
     */
    private void drawChair(ArrayNode shapes, String name, Pose p, ControlAgent ctl, boolean serial) {
        String safety = ctl == null ? "armed" : ctl.supervisor().state().name().toLowerCase(Locale.ROOT);
        boolean stopped = !safety.equals("armed");
        ObjectNode body = shapes.addObject().put("type", "circle").put("x", p.x()).put("y", p.y()).put("r", 0.45)
                .put("color", colour(name)).put("stroke", stopped ? "#c0392b" : "#ffffff").put("strokeWidth", stopped ? 0.16 : 0.05)
                .put("id", "chair-" + name).put("title", name + (serial ? " (serial)" : "") + (stopped && ctl != null ? ": " + safety(ctl) : ""));
        ObjectNode data = body.putObject("data").put("x", String.format(Locale.ROOT, "%.2f", p.x()))
                .put("y", String.format(Locale.ROOT, "%.2f", p.y())).put("safety", safety);
        if (serial) {
            data.put("serial", "true");
        }
        line(shapes, "#ffffff", 0.12, p.x(), p.y(), p.x() + 0.45 * Math.cos(p.heading()), p.y() + 0.45 * Math.sin(p.heading()));
        shapes.addObject().put("type", "text").put("x", p.x()).put("y", p.y() + 0.7).put("size", 0.6).put("color", "#1d2330").put("text", name);
    }

    /**
     * The battery as the chair's last report gave it (a simulated chair's model, a board's STATE
     * frame), with "low" while the chair reports its battery-low fault; empty before any report.
     */
    private static String battery(ControlAgent ctl) {
        ChairReadings r = ctl == null ? null : ctl.supervisor().latest();
        if (r == null) {
            return "";
        }
        return String.format(Locale.ROOT, "%.1f V", r.batteryVolts()) + (r.faults().contains(ChairFault.BATTERY_LOW) ? " low" : "");
    }

    /** A pose as the chairs' table shows it: metres on the map, and the heading in degrees (0 along x, 90 along y). */
    static String poseText(Pose p) {
        long deg = Math.round(Math.toDegrees(p.heading()));
        return String.format(Locale.ROOT, "(%.1f, %.1f) %d°", p.x(), p.y(), deg == -180 ? 180 : deg);
    }

    /** A row of "The chairs' tasks and bids": the chair, the task, its way, its state, its cost, why it ended. */
    private ArrayNode bidRow(String chair, TaskView t) {
        return json.createArrayNode().add(chair).add(t.id()).add(t.from() + " → " + t.to())
                .add(t.state().name().toLowerCase(Locale.ROOT)).add(String.format(Locale.ROOT, "%.0f s", t.costS()))
                .add(t.reason() == null ? "" : t.reason());
    }

    /** What the chair's safety supervisor says: armed, or held and why, with who may resume it. */
    private static String safety(ControlAgent ctl) {
        var s = ctl.supervisor();
        String state = switch (s.state()) {
            case ARMED -> "armed";
            case ARMING -> "re-arming";
            case OFFLINE -> "offline";
            case HELD -> "held: " + s.hold() + (s.hold().agentMayResume() ? "" : "; needs Resume");
        };
        // What it has seen since it started: e-stops, trips, reboots, refusals, links lost.
        StringBuilder seen = new StringBuilder();
        s.counts().forEach((k, v) -> {
            if (!k.equals("hold") && !k.equals("resume")) {
                seen.append(seen.length() == 0 ? "" : ", ").append(k).append(' ').append(v);
            }
        });
        // The link's dropped frames by reason (a serial chair): a technician's first clue (stale: a clock; corrupt: a cable).
        s.linkDrops().forEach((k, v) -> seen.append(seen.length() == 0 ? "" : ", ").append("dropped ").append(k).append(' ').append(v));
        return seen.length() == 0 ? state : state + " (" + seen + ")";
    }

    private static double toSegment(Pose p, Point a, Point b) {
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2));
        return Math.hypot(p.x() - (a.x() + t * dx), p.y() - (a.y() + t * dy));
    }

    private ObjectNode line(ArrayNode shapes, String color, double width, double... pts) {
        ObjectNode s = shapes.addObject().put("type", "line").put("color", color).put("width", width);
        ArrayNode a = s.putArray("points");
        for (double p : pts) {
            a.add(p);
        }
        return s;
    }

    private ObjectNode table(ArrayNode tables, String id, String title, List<String> columns, ArrayNode rows) {
        ObjectNode t = tables.addObject().put("id", id).put("title", title);
        ArrayNode c = t.putArray("columns");
        columns.forEach(c::add);
        t.set("rows", rows);
        return t;
    }
}
