package io.concord.agents.traffic;

import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.Content;
import io.concord.core.agent.Inbox;
import io.concord.agents.proto.Services;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.TickerBehaviour;
import io.concord.layers.platform.Platform;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Consumer;

/**
 * Keeps chairs apart on the map's route graph: a chair drives a route only once it holds every
 * node of it, and gives back each node as it leaves it.
 *
 * <p>Why whole routes: a chair that stands still holds one node (where it stands), a chair that
 * drives holds the rest of its route, and nobody else holds any of those. Two chairs can then
 * never meet on a node or an edge, and a chair waits only for chairs that stand still where it
 * must go. Such a wait ends by itself when the chair it waits for drives on; it does not when that
 * chair has nothing to do (it is moved out of the way) or waits in turn, round a cycle, for the
 * first (a deadlock: one chair of the cycle is moved out of the way). Out of the way is the
 * nearest node nobody stands on, that no waiting route and no granted route's end needs, reached
 * over free nodes; a dead end (a room, a parking place) is preferred to a corridor.
 *
 * <p>Messages (ontology {@code concord-wheelchair}), from a chair's control agent:
 * <ul>
 *   <li>REQUEST {@code reserve; at=<nodes it stands on>; path=<route>[; aside=true]}: it gives
 *       back everything but {@code at}, and is granted the route (INFORM {@code granted; path})
 *       at once or later, with an AGREE naming who is in the way meanwhile; a route that is not
 *       on the map is REFUSEd. A wait that cannot end (a silent chair stands on the route) gets a
 *       FAILURE with the reason.</li>
 *   <li>INFORM {@code release; node}: it has left the node.</li>
 *   <li>INFORM {@code idle; at}: it has nothing to do, standing at {@code at}.</li>
 *   <li>INFORM {@code here[; at=<nodes>]}: it is alive (its holds are kept), standing on those
 *       nodes; a chair says so as it sets off along each edge, so that a chair that falls silent
 *       keeps exactly the nodes its body takes.</li>
 * </ul>
 * To a chair: INFORM {@code make-way; from; to}: drive to {@code to} (held for it) and ask again
 * from there; its pending wait, if any, is answered FAILURE {@code make-way}.
 */
public class TrafficAgent extends Agent {
    /** A chair not heard of for this long keeps only the node it stands on; who waits for that node is told. */
    public static final long SILENT_MS = 60_000;
    private static final long REVIEW_MS = 1_000;

    private record Wait(String chair, List<Integer> path, AclMessage request, long since, boolean aside) {
    }

    private final HospitalMap map;
    private final Consumer<String> log;
    /** node -> the chairs holding it (two only when a chair's report contradicts a grant). */
    private final Map<Integer, Set<String>> holders = new TreeMap<>();
    /** chair -> the nodes it holds, where it stands first. */
    private final Map<String, List<Integer>> held = new TreeMap<>();
    private final Map<String, Wait> waiting = new LinkedHashMap<>();
    /** chair -> the end of the route it was granted last. */
    private final Map<String, Integer> goals = new HashMap<>();
    /** chair -> the node it was told to make way to, held for it until it asks for the route there. */
    private final Map<String, Integer> aside = new HashMap<>();
    private final Set<String> idle = new HashSet<>();
    private final Set<String> silent = new HashSet<>();
    private final Map<String, Long> heard = new HashMap<>();
    private final Map<String, AID> aids = new HashMap<>();
    /** chair -> the nodes it last said it stands on, less those it has given back since. */
    private final Map<String, List<Integer>> standing = new HashMap<>();
    private long grants;
    private long moves;
    private long deadlocks;
    private final boolean enabled;

    /**
     * @param map the route graph it reserves
     * @param log told of every chair moved out of the way and every silent chair
     */
    public TrafficAgent(HospitalMap map, Consumer<String> log) {
        this(map, log, true);
    }

    /**
     * For tests only: with {@code rules} false every route is granted at once, whoever holds its
     * nodes (the chairs then keep apart by their range sensors alone), to show what the
     * reservations do. Fixed at construction: nothing can switch a running traffic agent's rules off.
     */
    public TrafficAgent(HospitalMap map, Consumer<String> log, boolean rules) {
        this.map = map;
        this.log = log;
        this.enabled = rules;
    }

    @Override
    protected void setup() {
        Platform.of(this).register(ServiceDescription.of(Services.TRAFFIC, getLocalName()));
        MessageTemplate mine = MessageTemplate.matchOntology(Services.ONTOLOGY).and(
                MessageTemplate.matchPerformative(Performative.REQUEST).or(MessageTemplate.matchPerformative(Performative.INFORM)));
        Inbox.each(this, mine, this::handle);
        addBehaviour(new TickerBehaviour(this, REVIEW_MS) {
            @Override
            protected void onTick() {
                review();
            }
        });
    }

    // ---- what it can tell (tests, console) ------------------------------------------------------

    /** Who holds which node. */
    public Map<Integer, Set<String>> holders() {
        Map<Integer, Set<String>> out = new TreeMap<>();
        holders.forEach((k, v) -> {
            if (!v.isEmpty()) {
                out.put(k, Set.copyOf(v));
            }
        });
        return out;
    }

    /** Who waits for which route, and who is in the way. */
    public List<String> waits() {
        List<String> out = new ArrayList<>();
        for (Wait w : waiting.values()) {
            out.add(local(w.chair()) + " -> " + w.path() + " (in the way: " + blockers(w).stream().map(TrafficAgent::local).toList() + ")");
        }
        return out;
    }

    /** Routes granted so far. */
    public long grants() {
        return grants;
    }

    /** Chairs moved out of the way so far (idle ones in the way and deadlocks broken). */
    public long moves() {
        return moves;
    }

    /** Deadlocks found (each broken by moving a chair of it). */
    public long deadlocks() {
        return deadlocks;
    }

    // ---- messages -------------------------------------------------------------------------------

    private void handle(AclMessage m) {
        Content c = Content.parseOrAnswer(m, this::send);
        if (c == null) {
            return;
        }
        String chair = m.getSender().name();
        aids.put(chair, m.getSender());
        heard.put(chair, currentTimeMillis());
        if (silent.remove(chair)) {
            log.accept(getLocalName() + ": " + local(chair) + " is heard again");
        }
        try {
            switch (c.verb()) {
                case "reserve" -> reserve(chair, m, nodes(c, "at"), nodes(c, "path"), "true".equals(c.get("aside")));
                case "release" -> {
                    release(chair, c.integer("node"));
                    review();
                }
                case "idle" -> {
                    List<Integer> at = nodes(c, "at");
                    drop(chair, "idle");
                    hold(chair, at);
                    standing.put(chair, new ArrayList<>(at));
                    idle.add(chair);
                    goals.remove(chair);
                    review();
                }
                case "here" -> {
                    if (c.get("at") != null) {
                        standing.put(chair, new ArrayList<>(nodes(c, "at")));
                    }
                }
                default -> {
                    if (m.getPerformative() == Performative.REQUEST) {
                        send(m.createReply().setPerformative(Performative.NOT_UNDERSTOOD)
                                .setContent("traffic knows reserve, release, idle, here"));
                    }
                }
            }
        } catch (IllegalArgumentException e) {
            if (m.getPerformative() == Performative.REQUEST) {
                send(m.createReply().setPerformative(Performative.REFUSE).setContent(
                        Content.of("refuse").with("reason", e.getMessage()).toString()));
            }
        }
    }

    private List<Integer> nodes(Content c, String key) {
        List<Integer> out = new ArrayList<>();
        for (String s : c.list(key)) {
            int n;
            try {
                n = Integer.parseInt(s.trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(key + ": '" + s + "' is not a node id");
            }
            if (!map.hasNode(n)) {
                throw new IllegalArgumentException(key + ": there is no node " + n + " on " + map.name());
            }
            out.add(n);
        }
        return out;
    }

    private void reserve(String chair, AclMessage m, List<Integer> at, List<Integer> path, boolean asked) {
        if (path.isEmpty() || at.isEmpty()) {
            throw new IllegalArgumentException("a reservation needs the nodes the chair stands on (at) and a route (path)");
        }
        for (int i = 1; i < path.size(); i++) {
            if (map.edge(path.get(i - 1), path.get(i)).isEmpty()) {
                throw new IllegalArgumentException("the route has no edge " + path.get(i - 1) + "-" + path.get(i));
            }
        }
        Integer target = aside.get(chair);
        drop(chair, "a new route");
        List<Integer> keep = new ArrayList<>(at);
        if (asked && target != null && path.contains(target)) {
            // Stepping aside: the node it was sent to stays its own while it waits.
            aside.put(chair, target);
            keep.add(target);
        }
        hold(chair, keep);
        standing.put(chair, new ArrayList<>(at));
        idle.remove(chair);
        Wait w = new Wait(chair, List.copyOf(path), m, currentTimeMillis(), asked);
        if (!enabled || blockers(w).isEmpty()) {
            grant(w);
        } else {
            waiting.put(chair, w);
            send(m.createReply().setPerformative(Performative.AGREE).setContent(Content.of("reserve")
                    .with("held-by", String.join(",", blockers(w).stream().map(TrafficAgent::local).toList())).toString()));
        }
        review();
    }

    /** Forgets a chair's wait (answering it FAILURE) and every node it holds. */
    private void drop(String chair, String why) {
        Wait old = waiting.remove(chair);
        if (old != null) {
            send(old.request().createReply().setPerformative(Performative.FAILURE)
                    .setContent(Content.of("failure").with("reason", "superseded by " + why).toString()));
        }
        List<Integer> mine = held.remove(chair);
        if (mine != null) {
            for (int n : mine) {
                Set<String> h = holders.get(n);
                if (h != null) {
                    h.remove(chair);
                }
            }
        }
        aside.remove(chair);
    }

    private void hold(String chair, List<Integer> nodes) {
        List<Integer> mine = held.computeIfAbsent(chair, k -> new ArrayList<>());
        for (int n : nodes) {
            if (!mine.contains(n)) {
                mine.add(n);
            }
            holders.computeIfAbsent(n, k -> new LinkedHashSet<>()).add(chair);
        }
    }

    private void release(String chair, int node) {
        Set<String> h = holders.get(node);
        if (h != null) {
            h.remove(chair);
        }
        List<Integer> mine = held.get(chair);
        if (mine != null) {
            mine.remove(Integer.valueOf(node));
        }
        List<Integer> on = standing.get(chair);
        if (on != null) {
            on.remove(Integer.valueOf(node));
        }
        if (Integer.valueOf(node).equals(aside.get(chair))) {
            aside.remove(chair);
        }
    }

    private void grant(Wait w) {
        waiting.remove(w.chair());
        hold(w.chair(), w.path());
        goals.put(w.chair(), w.path().get(w.path().size() - 1));
        grants++;
        send(w.request().createReply().setPerformative(Performative.INFORM).setContent(Content.of("granted")
                .with("path", join(w.path())).toString()));
    }

    /** The chairs holding any node of a waiting route. */
    private List<String> blockers(Wait w) {
        List<String> out = new ArrayList<>();
        for (int n : w.path()) {
            for (String h : holders.getOrDefault(n, Set.of())) {
                if (!h.equals(w.chair()) && !out.contains(h)) {
                    out.add(h);
                }
            }
        }
        return out;
    }

    // ---- review: grants, chairs in the way, deadlocks, silence ----------------------------------

    /** Grants what has freed, moves idle chairs out of the way, breaks deadlocks, handles silent chairs. */
    private void review() {
        long now = currentTimeMillis();
        for (String chair : new ArrayList<>(held.keySet())) {
            if (!silent.contains(chair) && now - heard.getOrDefault(chair, now) > SILENT_MS) {
                silenced(chair);
            }
        }
        List<Wait> order = new ArrayList<>(waiting.values());
        // Chairs stepping aside first (others wait for them), then the longest waiting.
        order.sort(Comparator.comparing((Wait w) -> !w.aside()).thenComparingLong(Wait::since).thenComparing(Wait::chair));
        for (Wait w : order) {
            if (waiting.get(w.chair()) == w && blockers(w).isEmpty()) {
                grant(w);
            }
        }
        for (Wait w : new ArrayList<>(waiting.values())) {
            if (waiting.get(w.chair()) != w) {
                continue;
            }
            List<String> in = blockers(w);
            String gone = in.stream().filter(silent::contains).findFirst().orElse(null);
            if (gone != null) {
                waiting.remove(w.chair());
                send(w.request().createReply().setPerformative(Performative.FAILURE).setContent(Content.of("failure")
                        .with("node", firstHeldBy(w.path(), gone)).with("reason", local(gone) + " is silent and stands on the route")
                        .toString()));
                continue;
            }
            boolean moved = false;
            for (String h : in) {
                if (idle.contains(h) && !aside.containsKey(h)) {
                    moved |= makeWay(h, "it is idle in the way of " + local(w.chair()));
                }
            }
            if (moved) {
                continue;
            }
            List<String> cycle = cycle(w.chair());
            if (cycle.isEmpty() || cycle.stream().anyMatch(aside::containsKey)) {
                continue;
            }
            deadlocks++;
            List<String> victims = new ArrayList<>(cycle);
            victims.sort(null);
            for (String v : victims) {
                if (makeWay(v, "deadlock " + cycle.stream().map(TrafficAgent::local).toList())) {
                    break;
                }
            }
        }
    }

    private int firstHeldBy(List<Integer> path, String chair) {
        for (int n : path) {
            if (holders.getOrDefault(n, Set.of()).contains(chair)) {
                return n;
            }
        }
        return -1;
    }

    /**
     * A silent chair keeps where it stands: what it last said it stands on (a chair says so as it
     * sets off along each edge) and still holds, or else the first node it holds (it gives a node
     * back on reaching the next); the rest is given back.
     */
    private void silenced(String chair) {
        silent.add(chair);
        List<Integer> mine = held.getOrDefault(chair, List.of());
        List<Integer> body = new ArrayList<>(standing.getOrDefault(chair, List.of()));
        body.retainAll(mine);
        if (body.isEmpty() && !mine.isEmpty()) {
            body.add(mine.get(0));
        }
        Wait w = waiting.remove(chair);
        if (w != null) {
            send(w.request().createReply().setPerformative(Performative.FAILURE)
                    .setContent(Content.of("failure").with("reason", "silent for " + SILENT_MS / 1000 + " s").toString()));
        }
        for (int n : new ArrayList<>(mine)) {
            if (!body.contains(n)) {
                release(chair, n);
            }
        }
        log.accept(getLocalName() + ": " + local(chair) + " is silent; it keeps " + body + " where it stands");
    }

    /** A cycle of waits through {@code start}, or empty: each chair of it waits for a node the next holds. */
    private List<String> cycle(String start) {
        List<String> path = new ArrayList<>();
        return dfs(start, start, path, new HashSet<>()) ? path : List.of();
    }

    private boolean dfs(String start, String c, List<String> path, Set<String> seen) {
        path.add(c);
        Wait w = waiting.get(c);
        if (w != null) {
            for (String h : blockers(w)) {
                if (h.equals(start)) {
                    return true;
                }
                if (seen.add(h) && dfs(start, h, path, seen)) {
                    return true;
                }
            }
        }
        path.remove(path.size() - 1);
        return false;
    }

    /**
     * Sends a chair to the nearest node that nobody holds and nobody's route needs, over nodes
     * nobody else holds; prefers dead ends. False if there is no such node now.
     */
    private boolean makeWay(String chair, String why) {
        List<Integer> mine = held.get(chair);
        AID aid = aids.get(chair);
        if (mine == null || mine.isEmpty() || aid == null || silent.contains(chair)) {
            return false;
        }
        int from = mine.get(0);
        Set<Integer> needed = new HashSet<>();
        for (Wait w : waiting.values()) {
            if (!w.chair().equals(chair)) {
                needed.addAll(w.path());
            }
        }
        goals.forEach((c, g) -> {
            if (!c.equals(chair)) {
                needed.add(g);
            }
        });
        Map<Integer, Integer> hops = new HashMap<>();
        Map<Integer, Integer> prev = new HashMap<>();
        ArrayDeque<Integer> q = new ArrayDeque<>(List.of(from));
        hops.put(from, 0);
        int best = -1;
        int bestScore = Integer.MAX_VALUE;
        while (!q.isEmpty()) {
            int u = q.poll();
            for (Edge e : map.edgesAt(u)) {
                int v = e.other(u);
                if (hops.containsKey(v) || !freeFor(chair, v)) {
                    continue;
                }
                hops.put(v, hops.get(u) + 1);
                prev.put(v, u);
                q.add(v);
                if (!needed.contains(v)) {
                    int score = hops.get(v) + (map.edgesAt(v).size() == 1 ? 0 : 2);
                    if (score < bestScore || (score == bestScore && v < best)) {
                        best = v;
                        bestScore = score;
                    }
                }
            }
        }
        if (best < 0) {
            return false;
        }
        List<Integer> path = new ArrayList<>();
        for (int v = best; v != from; v = prev.get(v)) {
            path.add(0, v);
        }
        Wait own = waiting.remove(chair);
        if (own != null) {
            send(own.request().createReply().setPerformative(Performative.FAILURE)
                    .setContent(Content.of("failure").with("reason", "make-way").toString()));
        }
        idle.remove(chair);
        hold(chair, List.of(best));
        aside.put(chair, best);
        moves++;
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addReceiver(aid);
        m.setOntology(Services.ONTOLOGY);
        m.setContent(Content.of("make-way").with("from", from).with("to", best).with("path", join(path)).toString());
        send(m);
        log.accept(getLocalName() + ": " + local(chair) + " makes way from node " + from + " to node " + best + " (" + why + ")");
        return true;
    }

    private boolean freeFor(String chair, int node) {
        for (String h : holders.getOrDefault(node, Set.of())) {
            if (!h.equals(chair)) {
                return false;
            }
        }
        return true;
    }

    private static String join(List<Integer> nodes) {
        StringBuilder b = new StringBuilder();
        for (int n : nodes) {
            b.append(b.length() == 0 ? "" : ",").append(n);
        }
        return b.toString();
    }

    private static String local(String name) {
        int at = name.indexOf('@');
        return at < 0 ? name : name.substring(0, at);
    }
}
