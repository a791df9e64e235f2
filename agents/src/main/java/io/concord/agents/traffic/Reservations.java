package io.concord.agents.traffic;

import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.WheelchairMessage.Failure;

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
import java.util.TreeSet;

/**
 * The traffic rules, with no transport and no clock of their own: who holds which node of the
 * route graph, who waits for which route, who is moved out of the way, what a silent chair keeps.
 * {@link TrafficAgent} speaks for it; the rules are tested alone ({@code ReservationsTest}).
 *
 * <p>Each node has a queue of the chairs that hold it, in the order they were granted it; only the
 * first of a queue may be on the node or on an edge to it. A chair that stands still holds the node
 * it stands on; a chair granted a route joins the queue of every node of it, and drives into a node
 * only when it is first there (it is granted the route with how far it may drive now, {@link
 * Granted#upto()}, and told again, {@link Clear}, as the chairs ahead leave). A route is granted at
 * once unless a node of it is held by a chair that will not leave it (one that stands still there,
 * or ends its route there) or by a chair that is itself behind the asking one somewhere: then it
 * waits. So the queues' order is the order of grants, a chair waits only for chairs granted before
 * it, and a cycle of waits needs a chair that stands still (the proof is in docs/design.md). Such a
 * wait ends by itself when the chair it waits for drives on; it does not when that chair has
 * nothing to do (it is moved out of the way) or waits in turn, round a cycle, for the first (a
 * deadlock: one chair of the cycle that stands still is moved out of the way; if none can be, a
 * chair of it gives its grant back and asks again). With {@link TrafficRules#WHOLE_ROUTES} a route
 * is granted only when nobody else holds any node of it, and is driven whole. Out of the way is the
 * nearest node nobody stands on, that no waiting route and no granted route's end needs, reached
 * over free nodes, and not in a patient's room (an area of kind {@code room}); a dead end or one of
 * the map's parking places is preferred to a corridor. Only when no such node is free (a deadlock,
 * or an idle chair standing where another must go, with every other way held) is a chair sent into
 * a room.
 *
 * <p>A node chairs pass in lanes (a two-lane corridor running on through it: {@link
 * HospitalMap#laneAxis}) has a queue per lane instead: a route that keeps its lane there (straight
 * on, or turning off or onto the corridor on its right) joins only that lane's queue, any other
 * the queues of both. Two chairs driving opposite ways in their lanes share no queue and pass each
 * other; everything above holds with "node" read as "a node's lane, or the node".
 *
 * <p>Every call returns what the chairs are to be told, in order, as {@link Outcome}s; each answer
 * to a request carries the request's ticket (the agent's message, for its reply).
 *
 * @param <T> what identifies a request to answer (the traffic agent's REQUEST message)
 */
final class Reservations<T> {
    /** A chair not heard of for this long keeps only the node it stands on; who waits for that node is told. */
    public static final long SILENT_MS = 60_000;

    /** What a chair is to be told. */
    public sealed interface Outcome<T> {
    }

    /** The route is the chair's: drive it up to node {@code upto} (null: all of it), and wait there to be told {@link Clear}. */
    public record Granted<T>(String chair, T ticket, List<Integer> path, Integer upto) implements Outcome<T> {
    }

    /** The chair granted the route of {@code ticket} may drive on up to node {@code upto}: the chairs ahead have left. */
    public record Clear<T>(String chair, T ticket, int upto) implements Outcome<T> {
    }

    /** The route waits for the chairs in the way. */
    public record Waiting<T>(String chair, T ticket, List<String> heldBy) implements Outcome<T> {
    }

    /** The wait ended without the route: {@code node} is where it stuck, or null. */
    public record Failed<T>(String chair, T ticket, String reason, Integer node) implements Outcome<T> {
    }

    /** Drive from {@code from} to {@code to} over {@code path} (held for it), and ask again from there. */
    public record MakeWay<T>(String chair, int from, int to, List<Integer> path) implements Outcome<T> {
    }

    /** Something the operator should read (a chair moved, a chair silent or heard again). */
    public record Note<T>(String text) implements Outcome<T> {
    }

    /**
     * The fleet monitor's alarm: {@code chair} has work and has made no progress (left no node) since
     * {@code sinceMs}, for {@code forMs}; {@code waitsFor} says for what.
     */
    public record Stalled<T>(String chair, long sinceMs, long forMs, String waitsFor) implements Outcome<T> {
    }

    /** How long a chair is idle off the parking places before it is sent home (a next task usually comes sooner). */
    public static final long HOME_AFTER_MS = 30_000;

    /** How long a chair waits for idle chairs that none can move before its wait is refused ({@link #walledIn}). */
    public static final long WALLED_MS = 60_000;

    /** How long a chair sent aside shields a cycle it is in before the cycle is broken by the other rules. */
    public static final long ASIDE_GRACE_MS = 30_000;

    /** A route waiting for its grant; {@code keys}: what it takes at each node, worked out once (see {@link #keys}). */
    private record Wait<T>(String chair, List<Integer> path, List<long[]> keys, T ticket, long since, boolean aside) {
    }

    /**
     * A route granted in order: the chair may drive up to {@code path[upto]}; {@code keys[i]}: what
     * it takes at {@code path[i]} (its lane, or the whole node); {@code told}: it was told the
     * silent chair ahead.
     */
    private static final class Route<T> {
        final List<Integer> path;
        final List<long[]> keys;
        final T ticket;
        int upto;
        boolean told;

        Route(List<Integer> path, List<long[]> keys, T ticket) {
            this.path = path;
            this.keys = keys;
            this.ticket = ticket;
        }

        int next() {
            return upto + 1 < path.size() ? path.get(upto + 1) : -1;
        }
    }

    private final HospitalMap map;
    /** The map's parking places: where an idle chair stands best. */
    private final Set<Integer> parking;
    private final TrafficRules rules;
    private final TrafficSettings settings;
    /**
     * What is reserved, a key for each: a node ({@link #whole}), or one lane of a node chairs may
     * pass through in lanes (a two-lane corridor: {@link HospitalMap#laneAxis}), whose whole is
     * both its lanes. key -> the chairs holding it, in queue order.
     */
    private final Map<Long, Set<String>> holders = new TreeMap<>();
    /** chair -> the keys it holds, where it stands first. */
    private final Map<String, List<Long>> held = new TreeMap<>();
    private final Map<String, Wait<T>> waiting = new LinkedHashMap<>();
    /** chair -> the end of the route it was granted last. */
    private final Map<String, Integer> goals = new HashMap<>();
    /** chair -> the node it was told to make way to, held for it until it asks for the route there. */
    private final Map<String, Integer> aside = new HashMap<>();
    private final Set<String> idle = new HashSet<>();
    private final Set<String> silent = new HashSet<>();
    private final Map<String, Long> heard = new HashMap<>();
    /** chair -> when it last made progress, for every chair with work (not idle): the fleet monitor. */
    private final Map<String, Long> progressAt = new TreeMap<>();
    /**
     * Chairs the monitor has raised its alarm for, until they make progress again: chair -> how long
     * without progress its next alarm is due at (the limit, then twice, four times it: the alarm
     * is raised again as the wait goes on, less often the longer it lasts).
     */
    private final Map<String, Long> alarmed = new HashMap<>();
    /** chair -> when it was sent aside (its order shields a cycle it is in for {@link #ASIDE_GRACE_MS}). */
    private final Map<String, Long> asideSince = new HashMap<>();
    /** Chairs whose step aside was called off (not there within the grace), until they make progress: not sent aside again first. */
    private final Set<String> calledOff = new HashSet<>();
    /** chair -> since when its wait has been walled in ({@link #walledIn}). */
    private final Map<String, Long> walledSince = new HashMap<>();
    /** Idle chairs already sent home, until they ask for a route again. */
    private final Set<String> sentHome = new HashSet<>();
    /** Idle chairs off the parking places told to have no free place to go to (said once; tried again every review). */
    private final Set<String> homeless = new HashSet<>();
    /** chair -> since when it is idle. */
    private final Map<String, Long> idleSince = new HashMap<>();
    /** The time of the call being answered. */
    private long clock;
    private long alarms;
    /** chair -> the nodes it last said it stands on, less those it has given back since. */
    private final Map<String, List<Integer>> standing = new HashMap<>();
    /** chair -> its route granted in order, with its ticket and how far it may drive (index into the path). */
    private final Map<String, Route<T>> routes = new TreeMap<>();
    /** key -> since when the first chair of its queue has held it (it stands on it, or drives to it next). */
    private final Map<Long, Long> headSince = new HashMap<>();
    /** node -> how long a chair at the head of its queue has held it, on average (ms, a moving mean). */
    private final Map<Integer, Double> holdMs = new HashMap<>();
    /** What a node's hold is taken to be before any chair has given it back: a chair passing it. */
    public static final long PASS_MS = 5_000;
    private long grants;
    private long moves;
    private long deadlocks;
    private long unbroken;
    private long staleReleases;

    /**
     * @param map   the route graph it reserves
     * @param rules how; {@link TrafficRules#NONE} only in tests
     */
    public Reservations(HospitalMap map, TrafficRules rules) {
        this(map, TrafficSettings.standard().withRules(rules));
    }

    /** With liveness settings (the monitor's limit; tests switch rules off). */
    public Reservations(HospitalMap map, TrafficSettings settings) {
        this.map = map;
        this.parking = Set.copyOf(map.parking());
        this.rules = settings.rules();
        this.settings = settings;
    }

    /** Alarms the fleet monitor has raised so far. */
    public long alarms() {
        return alarms;
    }

    /** For each chair with work: when it last made progress (the fleet monitor's view). */
    public Map<String, Long> lastProgress() {
        return Map.copyOf(progressAt);
    }

    /**
     * The chair made progress: it left a node (a grant or a clearance is not progress until the chair
     * drives on it). Its alarm, if any, ends.
     */
    private void progressed(String chair, List<Outcome<T>> out) {
        if (progressAt.containsKey(chair)) {
            progressAt.put(chair, clock);
        }
        calledOff.remove(chair);
        if (alarmed.remove(chair) != null) {
            out.add(new Note<>(local(chair) + " makes progress again"));
        }
    }

    // ---- what it can tell -----------------------------------------------------------------------

    /**
     * Who holds which node, in the node's queue order (the first may be on it); for a node with
     * lanes, lane 0's queue and then the chairs only in lane 1's ({@link #lanes()} has both).
     */
    public Map<Integer, List<String>> holders() {
        Map<Integer, List<String>> out = new TreeMap<>();
        holders.forEach((k, v) -> {
            if (!v.isEmpty()) {
                List<String> q = out.computeIfAbsent(node(k), n -> new ArrayList<>());
                v.stream().filter(c -> !q.contains(c)).forEach(q::add);
            }
        });
        out.replaceAll((k, v) -> List.copyOf(v));
        return out;
    }

    /** For each node with lanes that somebody holds: its two lanes' queues, lane 0 first (the first of each may be in it). */
    public Map<Integer, List<List<String>>> lanes() {
        Map<Integer, List<List<String>>> out = new TreeMap<>();
        holders.forEach((k, v) -> {
            if (!v.isEmpty() && kind(k) != WHOLE) {
                out.computeIfAbsent(node(k), n -> new ArrayList<>(List.of(List.of(), List.of()))).set(kind(k) - 1, List.copyOf(v));
            }
        });
        out.replaceAll((k, v) -> List.copyOf(v));
        return out;
    }

    /** Each chair's granted route still ahead of it, and how far it may drive now: {@code chair -> [path, upto]}. */
    public Map<String, List<Integer>> cleared() {
        Map<String, List<Integer>> out = new TreeMap<>();
        routes.forEach((c, r) -> out.put(c, List.copyOf(r.path.subList(0, r.upto + 1))));
        return out;
    }

    /**
     * How long {@code chair} should expect to wait for the chairs ahead of it on {@code path}, from
     * the reservations now (seconds): every other chair that holds or is queued for what the path
     * takes at one of its nodes, counted once, for as long as chairs have held the longest-held of
     * those nodes on average ({@link #PASS_MS} at a node nobody has given back yet). A chair alone
     * on its way waits 0. What a bid adds to its quote (docs/design.md, "Quotes that include waiting").
     */
    public double expectedWaitS(String chair, List<Integer> path) {
        Map<String, Double> ahead = new TreeMap<>();
        List<long[]> ks = keys(path);
        for (int i = 0; i < path.size(); i++) {
            double ms = holdMs.getOrDefault(path.get(i), (double) PASS_MS);
            for (long k : ks.get(i)) {
                Set<String> h = holders.get(k);
                if (h != null) {
                    for (String c : h) {
                        if (!c.equals(chair)) {
                            ahead.merge(c, ms, Math::max);
                        }
                    }
                }
            }
        }
        return ahead.values().stream().mapToDouble(Double::doubleValue).sum() / 1000.0;
    }

    /** Who waits for which route, and who is in the way. */
    public List<String> waits() {
        List<String> out = new ArrayList<>();
        for (Wait<T> w : waiting.values()) {
            out.add(local(w.chair()) + " -> " + w.path() + " (in the way: " + blockers(w).stream().map(Reservations::local).toList() + ")");
        }
        routes.forEach((c, r) -> {
            List<String> ahead = waitsFor(c);
            if (!ahead.isEmpty()) {
                out.add(local(c) + " -> " + r.path + " at node " + r.path.get(r.upto) + " (ahead at node " + r.next() + ": "
                        + ahead.stream().map(Reservations::local).toList() + ")");
            }
        });
        return out;
    }

    /** Releases of a node ahead of the chair on its granted route, kept for it ({@link #release}). */
    public long staleReleases() {
        return staleReleases;
    }

    /** Routes granted so far. */
    public long grants() {
        return grants;
    }

    /** Chairs moved out of the way so far (idle ones in the way and deadlocks broken). */
    public long moves() {
        return moves;
    }

    /** Deadlocks broken (by moving a chair of each aside, or taking a grant back). */
    public long deadlocks() {
        return deadlocks;
    }

    /**
     * Reviews that found a deadlock nobody could break then (no free node to step aside to, no
     * grant to take back): it waits for a chair elsewhere to free a node. Counted once a review.
     */
    public long deadlockReviewsUnbroken() {
        return unbroken;
    }

    // ---- what chairs say ------------------------------------------------------------------------

    /** A chair was heard from (any message): its holds are kept; a silent one is heard again. */
    public List<Outcome<T>> heard(String chair, long nowMs) {
        List<Outcome<T>> out = new ArrayList<>();
        heard.put(chair, nowMs);
        if (silent.remove(chair)) {
            out.add(new Note<>(local(chair) + " is heard again"));
        }
        return out;
    }

    /**
     * A chair standing on {@code at} asks for {@code path} ({@code asked}: the route to where it was
     * told to make way): it gives back everything else, and is granted the route or waits.
     *
     * @throws IllegalArgumentException for a route that is not on the map (nothing changes)
     */
    public List<Outcome<T>> reserve(String chair, T ticket, List<Integer> at, List<Integer> path, boolean asked, long nowMs) {
        if (path.isEmpty() || at.isEmpty()) {
            throw new IllegalArgumentException("a reservation needs the nodes the chair stands on (at) and a route (path)");
        }
        for (int i = 1; i < path.size(); i++) {
            if (map.edge(path.get(i - 1), path.get(i)).isEmpty()) {
                throw new IllegalArgumentException("the route has no edge " + path.get(i - 1) + "-" + path.get(i));
            }
        }
        List<Outcome<T>> out = new ArrayList<>();
        clock = nowMs;
        progressAt.putIfAbsent(chair, nowMs);
        walledSince.remove(chair);
        sentHome.remove(chair);
        homeless.remove(chair);
        idleSince.remove(chair);
        Integer target = aside.get(chair);
        List<Long> keep = wholes(at);
        boolean stepping = asked && target != null && path.contains(target);
        if (stepping) {
            keep.addAll(wholes(List.of(target)));
        }
        drop(chair, "a new route", out, keep);
        if (stepping) {
            // Stepping aside: the node it was sent to stays its own while it waits.
            aside.put(chair, target);
        }
        hold(chair, keep);
        standing.put(chair, new ArrayList<>(at));
        idle.remove(chair);
        Wait<T> w = new Wait<>(chair, List.copyOf(path), keys(path), ticket, nowMs, asked);
        if (rules == TrafficRules.NONE || blockers(w).isEmpty()) {
            grant(w, out);
        } else {
            waiting.put(chair, w);
            out.add(new Waiting<>(chair, ticket, blockers(w).stream().map(Reservations::local).toList()));
        }
        review(nowMs, out);
        return out;
    }

    /**
     * A chair has left a node. A node still ahead of it on its granted route is not given back (it
     * cannot have left a node it has not reached): such a release is a late answer to an order to
     * make way there, sent before this agent had the chair's request for a route through that node
     * (the chair, granted it meanwhile, refused the order); obeying it would clear another chair
     * into the node this one will drive into.
     */
    public List<Outcome<T>> release(String chair, int node, long nowMs) {
        List<Outcome<T>> out = new ArrayList<>();
        clock = nowMs;
        if (settings.on(TrafficSettings.Rule.RELEASE_BEHIND) && ahead(chair, node)) {
            staleReleases++;
            out.add(new Note<>(local(chair) + " gave back node " + node + ", ahead of it on its route: kept for it"
                    + " (a late answer; " + staleReleases + " so far)"));
            return out;
        }
        if (holds(chair, node)) {
            progressed(chair, out);
        }
        giveBack(chair, node);
        review(nowMs, out);
        return out;
    }

    /** A chair has nothing to do, standing on {@code at}. */
    public List<Outcome<T>> idle(String chair, List<Integer> at, long nowMs) {
        List<Outcome<T>> out = new ArrayList<>();
        List<Long> keep = wholes(at);
        drop(chair, "idle", out, keep);
        hold(chair, keep);
        standing.put(chair, new ArrayList<>(at));
        idle.add(chair);
        idleSince.putIfAbsent(chair, nowMs);
        goals.remove(chair);
        clock = nowMs;
        progressAt.remove(chair);
        calledOff.remove(chair);
        if (alarmed.remove(chair) != null) {
            out.add(new Note<>(local(chair) + " is idle now"));
        }
        review(nowMs, out);
        return out;
    }

    /** A chair says where it stands (as it sets off along each edge). */
    public void standing(String chair, List<Integer> at) {
        standing.put(chair, new ArrayList<>(at));
    }

    /** Time passed: grants what has freed, moves idle chairs out of the way, breaks deadlocks, handles silent chairs. */
    public List<Outcome<T>> review(long nowMs) {
        List<Outcome<T>> out = new ArrayList<>();
        clock = nowMs;
        review(nowMs, out);
        return out;
    }

    // ---- the rules ------------------------------------------------------------------------------

    /**
     * Forgets a chair's wait (answering it FAILURE) and every node it holds but {@code keep} (where
     * it stands: it keeps its place in those nodes' queues).
     */
    private void drop(String chair, String why, List<Outcome<T>> out, List<Long> keep) {
        Wait<T> old = waiting.remove(chair);
        if (old != null) {
            out.add(new Failed<>(chair, old.ticket(), "superseded by " + why, null));
        }
        List<Long> mine = held.remove(chair);
        if (mine != null) {
            List<Long> kept = new ArrayList<>();
            for (long n : keep) {
                if (mine.contains(n) && !kept.contains(n)) {
                    kept.add(n);
                }
            }
            for (long n : mine) {
                Set<String> h = holders.get(n);
                if (h != null && !keep.contains(n)) {
                    boolean head = !h.isEmpty() && h.iterator().next().equals(chair);
                    h.remove(chair);
                    if (head) {
                        headSince.remove(n);
                        if (!h.isEmpty()) {
                            headSince.put(n, clock);
                        }
                    }
                }
            }
            if (!kept.isEmpty()) {
                held.put(chair, kept);
            }
        }
        aside.remove(chair);
        routes.remove(chair);
    }

    private void hold(String chair, List<Long> keys) {
        List<Long> mine = held.computeIfAbsent(chair, k -> new ArrayList<>());
        for (long n : keys) {
            if (!mine.contains(n)) {
                mine.add(n);
            }
            Set<String> h = holders.computeIfAbsent(n, k -> new LinkedHashSet<>());
            if (h.isEmpty()) {
                headSince.put(n, clock);
            }
            h.add(chair);
        }
    }

    /** Gives back the node: whatever of it (its lanes, or all of it) the chair holds. */
    private void giveBack(String chair, int node) {
        for (int kind = WHOLE; kind <= LANE_1; kind++) {
            giveBackKey(chair, key(node, kind));
        }
        List<Integer> on = standing.get(chair);
        if (on != null) {
            on.remove(Integer.valueOf(node));
        }
        if (Integer.valueOf(node).equals(aside.get(chair))) {
            aside.remove(chair);
        }
    }

    private void giveBackKey(String chair, long key) {
        Set<String> h = holders.get(key);
        if (h != null && !h.isEmpty() && h.iterator().next().equals(chair)) {
            // The head leaves: how long it held the node (standing, loading, waiting on) teaches the estimate.
            Long since = headSince.remove(key);
            if (since != null) {
                holdMs.merge(node(key), (double) Math.max(0, clock - since), (old, d) -> 0.8 * old + 0.2 * d);
            }
            h.remove(chair);
            if (!h.isEmpty()) {
                headSince.put(key, clock);
            }
        } else if (h != null) {
            h.remove(chair);
        }
        List<Long> mine = held.get(chair);
        if (mine != null) {
            mine.remove(Long.valueOf(key));
        }
    }

    // ---- what a chair takes at a node: the node, or its lane -------------------------------------

    private static final int WHOLE = 0;
    private static final int LANE_0 = 1;
    private static final int LANE_1 = 2;

    private static long key(int node, int kind) {
        return ((long) node << 2) | kind;
    }

    private static int node(long key) {
        return (int) (key >> 2);
    }

    private static int kind(long key) {
        return (int) (key & 3);
    }

    /** A whole node: both its lanes if it has lanes, else the node. */
    private long[] whole(int node) {
        return map.laned(node) ? new long[] {key(node, LANE_0), key(node, LANE_1)} : new long[] {key(node, WHOLE)};
    }

    private List<Long> wholes(List<Integer> nodes) {
        List<Long> out = new ArrayList<>();
        for (int n : nodes) {
            for (long k : whole(n)) {
                out.add(k);
            }
        }
        return out;
    }

    /**
     * What a route takes at each of its nodes: in order, only its lane where it passes straight
     * through a node with lanes; else (and by other rules) the whole node.
     */
    private List<long[]> keys(List<Integer> path) {
        List<long[]> out = new ArrayList<>();
        for (int i = 0; i < path.size(); i++) {
            int lane = rules != TrafficRules.IN_ORDER || i == 0 || i == path.size() - 1 ? -1
                    : map.lane(path.get(i - 1), path.get(i), path.get(i + 1));
            out.add(lane < 0 ? whole(path.get(i)) : new long[] {key(path.get(i), lane == 0 ? LANE_0 : LANE_1)});
        }
        return out;
    }

    private static List<Long> flat(List<long[]> keys) {
        List<Long> out = new ArrayList<>();
        for (long[] ks : keys) {
            for (long k : ks) {
                out.add(k);
            }
        }
        return out;
    }

    /** Whether the chair is first in the queue of every key. */
    private boolean heads(String chair, long[] keys) {
        for (long k : keys) {
            if (!chair.equals(head(k))) {
                return false;
            }
        }
        return true;
    }

    private void grant(Wait<T> w, List<Outcome<T>> out) {
        waiting.remove(w.chair());
        List<long[]> keys = w.keys();
        hold(w.chair(), flat(keys));
        goals.put(w.chair(), w.path().get(w.path().size() - 1));
        grants++;
        if (rules != TrafficRules.IN_ORDER) {
            out.add(new Granted<>(w.chair(), w.ticket(), w.path(), null));
            return;
        }
        Route<T> r = new Route<>(w.path(), keys, w.ticket());
        routes.put(w.chair(), r);
        advance(w.chair(), r);
        out.add(new Granted<>(w.chair(), w.ticket(), w.path(), r.path.get(r.upto)));
    }

    /**
     * Moves a route's {@code upto} on over every node whose queues the chair now heads (and, to set
     * off from a node with lanes, both its lanes: a chair that stopped in one and turns there waits
     * for the other lane's chairs ahead of it); true if it moved.
     */
    private boolean advance(String chair, Route<T> r) {
        int before = r.upto;
        while (r.upto + 1 < r.path.size() && heads(chair, r.keys.get(r.upto + 1)) && (r.upto > 0 || setsOff(chair, r))
                && admitted(chair, r, r.upto + 1) == null) {
            r.upto++;
        }
        return r.upto != before;
    }

    /**
     * Admission: the chair that would stand still at node {@code path[i]}'s next node, keeping the
     * chair from driving into {@code path[i]} (it could not leave it: the next node of its route is
     * held, ahead of it, by a chair that will not drive on), or null if it may. Its route's end is
     * always admitted: it stays there.
     */
    private String admitted(String chair, Route<T> r, int i) {
        if (!settings.on(TrafficSettings.Rule.ADMISSION) || rules != TrafficRules.IN_ORDER || i + 1 >= r.path.size()) {
            return null;
        }
        for (long k : r.keys.get(i + 1)) {
            for (String h : holders.getOrDefault(k, Set.of())) {
                if (h.equals(chair)) {
                    break; // the rest of the queue is behind it
                }
                if (!passes(h, k)) {
                    return h;
                }
            }
        }
        return null;
    }

    private boolean setsOff(String chair, Route<T> r) {
        return !map.laned(r.path.get(0)) || heads(chair, r.keys.get(0));
    }

    /** The chair first in a key's queue, or null. */
    private String head(long key) {
        Set<String> h = holders.get(key);
        return h == null || h.isEmpty() ? null : h.iterator().next();
    }

    /**
     * The chairs a waiting route waits for. Whole routes: whoever holds a node of it. In order:
     * whoever holds a node of it and will not drive through it (it stands or ends there, or is
     * silent), or is behind the asking chair in some queue (the asking chair would then wait for a
     * chair that waits for it).
     */
    private List<String> blockers(Wait<T> w) {
        List<String> out = new ArrayList<>();
        Set<String> behind = rules == TrafficRules.IN_ORDER ? behind(w.chair()) : Set.of();
        for (long n : flat(w.keys())) {
            for (String h : holders.getOrDefault(n, Set.of())) {
                if (!h.equals(w.chair()) && !out.contains(h)
                        && (rules != TrafficRules.IN_ORDER || !passes(h, n) || behind.contains(h))) {
                    out.add(h);
                }
            }
        }
        return out;
    }

    /** The chairs a chair waits for: those its waiting route waits for, or the one ahead of it where its granted route stops. */
    private List<String> waitsFor(String chair) {
        Wait<T> w = waiting.get(chair);
        if (w != null) {
            return blockers(w);
        }
        Route<T> r = routes.get(chair);
        List<String> out = new ArrayList<>();
        if (r != null && r.next() >= 0) {
            List<long[]> at = r.upto == 0 && !setsOff(chair, r) ? List.of(r.keys.get(0)) : List.of(r.keys.get(r.upto + 1));
            for (long[] ks : at) {
                for (long k : ks) {
                    String h = head(k);
                    if (h != null && !h.equals(chair) && !out.contains(h)) {
                        out.add(h);
                    }
                }
            }
            if (out.isEmpty() && (r.upto > 0 || setsOff(chair, r))) {
                // Held back by admission: it waits for the chair that stands where it would have to go next.
                String h = admitted(chair, r, r.upto + 1);
                if (h != null) {
                    out.add(h);
                }
            }
        }
        return out;
    }

    /** Whether {@code chair} will drive on through {@code key}: it is on its granted route, not its end, and the chair is heard. */
    private boolean passes(String chair, long key) {
        Route<T> r = routes.get(chair);
        if (r == null || silent.contains(chair) || idle.contains(chair) || aside.containsKey(chair)) {
            return false;
        }
        for (int i = 0; i < r.keys.size() - 1; i++) {
            for (long k : r.keys.get(i)) {
                if (k == key) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Every chair behind {@code chair} in some node's queue, and behind those, and so on. */
    private Set<String> behind(String chair) {
        Set<String> out = new HashSet<>();
        ArrayDeque<String> todo = new ArrayDeque<>(List.of(chair));
        while (!todo.isEmpty()) {
            String c = todo.poll();
            for (long n : held.getOrDefault(c, List.of())) {
                boolean after = false;
                for (String h : holders.getOrDefault(n, Set.of())) {
                    if (after && out.add(h)) {
                        todo.add(h);
                    }
                    after |= h.equals(c);
                }
            }
        }
        return out;
    }

    private void review(long now, List<Outcome<T>> out) {
        for (String chair : new ArrayList<>(held.keySet())) {
            if (!silent.contains(chair) && now - heard.getOrDefault(chair, now) > SILENT_MS) {
                silenced(chair, out);
            }
        }
        List<Wait<T>> order = new ArrayList<>(waiting.values());
        // Chairs stepping aside first (others wait for them), then the longest waiting.
        order.sort(Comparator.comparing((Wait<T> w) -> !w.aside()).thenComparingLong(Wait::since).thenComparing(Wait::chair));
        for (Wait<T> w : order) {
            if (waiting.get(w.chair()) == w && blockers(w).isEmpty()) {
                grant(w, out);
            }
        }
        for (Map.Entry<String, Route<T>> e : routes.entrySet()) {
            Route<T> r = e.getValue();
            if (advance(e.getKey(), r)) {
                out.add(new Clear<>(e.getKey(), r.ticket, r.path.get(r.upto)));
            }
        }
        List<String> stuck = new ArrayList<>(waiting.keySet());
        routes.forEach((c, r) -> {
            if (!waitsFor(c).isEmpty()) {
                stuck.add(c);
            }
        });
        for (String chair : stuck) {
            Wait<T> w = waiting.get(chair);
            Route<T> granted = w == null ? routes.get(chair) : null;
            if (w == null && granted == null) {
                continue;
            }
            List<String> in = waitsFor(chair);
            if (in.isEmpty()) {
                continue;
            }
            String gone = in.stream().filter(silent::contains).findFirst().orElse(null);
            if (gone != null) {
                String why = local(gone) + " is silent and stands on the route";
                if (w != null) {
                    waiting.remove(chair);
                    out.add(new Failed<>(chair, w.ticket(), why, firstHeldBy(w.path(), gone)));
                } else if (!granted.told) {
                    granted.told = true;
                    out.add(new Failed<>(chair, granted.ticket, why, granted.next()));
                }
                continue;
            }
            boolean moved = false;
            for (String h : in) {
                if (idle.contains(h) && !aside.containsKey(h)) {
                    String why = "it is idle in the way of " + local(chair);
                    // A room only if nothing else is free: it stands where the other must go (its destination, say).
                    moved |= makeWay(h, why, false, out) || makeWay(h, why, true, out)
                            || (anyCycle() && (makeWay(h, why, false, out, Set.of(chair)) || makeWay(h, why, true, out, Set.of(chair))))
                            || push(h, chair, out);
                }
            }
            if (moved) {
                walledSince.remove(chair);
                continue;
            }
            if (w != null && walledIn(chair, w, in, now, out)) {
                continue;
            }
            List<String> cycle = cycle(chair);
            if (cycle.isEmpty()) {
                continue;
            }
            List<String> shielding = cycle.stream().filter(aside::containsKey).toList();
            if (!shielding.isEmpty()) {
                // A chair of it is on its way aside: the cycle ends when it gets there. Unless it
                // has not, within the grace: then its order no longer shields the cycle.
                if (!settings.on(TrafficSettings.Rule.ANY_CYCLE)
                        || shielding.stream().anyMatch(c -> now - asideSince.getOrDefault(c, now) < ASIDE_GRACE_MS)) {
                    continue;
                }
                for (String c : shielding) {
                    cancelAside(c, "deadlock " + cycle.stream().map(Reservations::local).toList(), out);
                }
            }
            String why = "deadlock " + cycle.stream().map(Reservations::local).toList();
            // A chair that stands still steps aside; one granted a route ahead of others cannot (it is under way).
            List<String> victims = new ArrayList<>(cycle);
            victims.removeIf(routes::containsKey);
            victims.sort(null);
            // A chair whose last step aside was called off is not sent aside again first (it could not
            // get there, and the same order would come round for ever): a granted chair of the cycle
            // gives its route back before it is asked again.
            List<String> again = new ArrayList<>(victims);
            if (anyCycle()) {
                victims.removeIf(calledOff::contains);
                again.removeAll(victims);
            } else {
                again.clear();
            }
            boolean broken = false;
            for (String v : victims) {
                if (makeWay(v, why, false, out) || makeWay(v, why, true, out)) {
                    broken = true;
                    break;
                }
            }
            if (!broken && anyCycle()) {
                // Gridlock: no node is free that no waiting route needs. A node only routes outside
                // the cycle need will do: those chairs wait anyway, and the cycle moves on.
                Set<String> members = Set.copyOf(cycle);
                for (String v : victims) {
                    if (makeWay(v, why, false, out, members) || makeWay(v, why, true, out, members)) {
                        broken = true;
                        break;
                    }
                }
            }
            if (!broken) {
                // Nobody can step aside: a granted chair of the cycle gives back all but where it stands and asks again.
                List<String> granteds = new ArrayList<>(cycle);
                granteds.retainAll(routes.keySet());
                granteds.sort(null);
                if (!granteds.isEmpty()) {
                    withdraw(granteds.get(0), why, out);
                    broken = true;
                }
            }
            for (String v : again) {
                if (broken) {
                    break;
                }
                broken = makeWay(v, why, false, out) || makeWay(v, why, true, out)
                        || makeWay(v, why, false, out, Set.copyOf(cycle)) || makeWay(v, why, true, out, Set.copyOf(cycle));
            }
            if (broken) {
                deadlocks++;
            } else {
                unbroken++;
            }
        }
        home(out);
        monitor(now, out);
    }

    /**
     * The fleet monitor: every chair with work that has made no progress for the limit raises an
     * alarm naming what it waits for, and again at twice the limit, four times, and so on, until it
     * makes progress (a wait nobody ends is not reported once and then forgotten).
     */
    private void monitor(long now, List<Outcome<T>> out) {
        if (!settings.on(TrafficSettings.Rule.ALARM)) {
            return;
        }
        for (Map.Entry<String, Long> e : progressAt.entrySet()) {
            String chair = e.getKey();
            long without = now - e.getValue();
            long due = alarmed.getOrDefault(chair, settings.stallMs());
            if (without >= due && !idle.contains(chair)) {
                alarmed.put(chair, 2 * due);
                alarms++;
                out.add(new Stalled<>(chair, e.getValue(), without, waitDescription(chair)));
            }
        }
    }

    /** What a chair waits for, in words, for the alarm. */
    private String waitDescription(String chair) {
        if (silent.contains(chair)) {
            return "nothing: it is silent";
        }
        Wait<T> w = waiting.get(chair);
        if (w != null) {
            return "its route " + w.path() + (w.aside() ? " aside" : "") + " (in the way: " + blockers(w).stream().map(Reservations::local).toList() + ")";
        }
        Route<T> r = routes.get(chair);
        if (r != null && r.next() >= 0) {
            List<String> ahead = waitsFor(chair);
            if (!ahead.isEmpty()) {
                return "its turn at node " + r.next() + " of its route " + r.path + " (ahead: " + ahead.stream().map(Reservations::local).toList() + ")";
            }
            return "nothing the traffic agent holds back: it may drive to node " + r.path.get(r.upto) + " of " + r.path
                    + " (a door, its sensors, the chair itself)";
        }
        if (r != null) {
            return "nothing the traffic agent holds back: all of its route " + r.path + " is cleared, it stands at "
                    + standing.getOrDefault(chair, List.of()) + " (its patient, a plan, a door, its sensors, a hold)";
        }
        return "nothing the traffic agent holds back: it stands at " + standing.getOrDefault(chair, List.of())
                + " with no route asked (a plan, a door, its patient, a hold)";
    }

    /**
     * Idle chairs go home: one idle for {@link #HOME_AFTER_MS} off the map's parking places (in a patient's room, say) is sent to
     * the nearest parking place nobody holds or needs, by hops over free nodes, ties in the map's
     * order of places; once until it asks for a route again. While no place is free it is said
     * once, and tried again at every review (a chair stayed in a patient's room for good when the
     * one try found the depot's places held for a moment).
     */
    private void home(List<Outcome<T>> out) {
        if (!settings.on(TrafficSettings.Rule.HOME) || parking.isEmpty() || rules != TrafficRules.IN_ORDER) {
            return;
        }
        for (String chair : new ArrayList<>(new TreeSet<>(idle))) {
            List<Long> mine = held.get(chair);
            if (sentHome.contains(chair) || aside.containsKey(chair) || mine == null || mine.isEmpty() || silent.contains(chair)) {
                continue;
            }
            int at = node(mine.get(0));
            if (parking.contains(at) || clock - idleSince.getOrDefault(chair, clock) < HOME_AFTER_MS) {
                continue;
            }
            if (goHome(chair, at, out)) {
                sentHome.add(chair);
                homeless.remove(chair);
            } else if (homeless.add(chair)) {
                out.add(new Note<>(local(chair) + " is idle at node " + at + ", off the parking places, and none is free to go to;"
                        + " it goes when one is"));
            }
        }
    }

    /** Sends the chair to the nearest free parking place; false if there is none it can reach now. */
    private boolean goHome(String chair, int from, List<Outcome<T>> out) {
        Map<Integer, Integer> prev = new HashMap<>();
        ArrayDeque<Integer> q = new ArrayDeque<>(List.of(from));
        prev.put(from, from);
        Set<Integer> needed = needed(chair, null);
        List<Integer> order = map.parking();
        int best = -1;
        while (!q.isEmpty() && best < 0) {
            // one ring of hops at a time: the first ring with a free place, its first by the map's order
            List<Integer> ring = new ArrayList<>(q);
            q.clear();
            List<Integer> next = new ArrayList<>();
            for (int u : ring) {
                for (Edge e : map.edgesAt(u)) {
                    int v = e.other(u);
                    if (!prev.containsKey(v) && freeFor(chair, v)) {
                        prev.put(v, u);
                        next.add(v);
                    }
                }
            }
            int bestRank = Integer.MAX_VALUE;
            for (int v : next) {
                int rank = order.indexOf(v);
                if (rank >= 0 && !needed.contains(v) && rank < bestRank) {
                    best = v;
                    bestRank = rank;
                }
            }
            q.addAll(next);
        }
        if (best < 0) {
            return false;
        }
        List<Integer> path = new ArrayList<>();
        for (int v = best; v != from; v = prev.get(v)) {
            path.add(0, v);
        }
        idle.remove(chair);
        hold(chair, wholes(List.of(best)));
        aside.put(chair, best);
        asideSince.put(chair, clock);
        out.add(new MakeWay<>(chair, from, best, List.copyOf(path)));
        out.add(new Note<>(local(chair) + " goes home from node " + from + " to parking place " + best + " (it is idle)"));
        return true;
    }

    /**
     * A chair sent aside that has not got there within the grace, in a cycle: its order ends (the
     * node kept for it is given back unless it stands there; its route there, granted or waiting,
     * is taken back, FAILURE), and it counts as any other chair of the cycle.
     */
    private void cancelAside(String chair, String why, List<Outcome<T>> out) {
        calledOff.add(chair);
        Integer target = aside.remove(chair);
        asideSince.remove(chair);
        Wait<T> w = waiting.remove(chair);
        if (w != null) {
            out.add(new Failed<>(chair, w.ticket(), why + ": the step aside to node " + target + " is called off, ask again", null));
        }
        Route<T> r = routes.get(chair);
        List<Integer> body = body(chair, r != null ? r.path.get(r.upto) : null);
        if (r != null) {
            routes.remove(chair);
            goals.remove(chair);
            out.add(new Failed<>(chair, r.ticket, why + ": the step aside to node " + target + " is called off, ask again", null));
        }
        if (!body.isEmpty()) {
            keepOnly(chair, body);
        } else if (target != null && !standing.getOrDefault(chair, List.of()).contains(target)) {
            giveBack(chair, target);
        }
        out.add(new Note<>(local(chair) + " has not made way to node " + target + " within " + ASIDE_GRACE_MS / 1000
                + " s; the order is called off, keeping " + body + " (" + why + ")"));
    }

    /**
     * Takes a granted route back (a deadlock nobody could step aside from): the chair keeps what it
     * stands on, and is told FAILURE with no node, so that it plans again from where it is.
     */
    private void withdraw(String chair, String why, List<Outcome<T>> out) {
        Route<T> r = routes.remove(chair);
        List<Integer> body = body(chair, r.path.get(r.upto));
        keepOnly(chair, body);
        goals.remove(chair);
        moves++;
        out.add(new Failed<>(chair, r.ticket, why + ": the route is given back, ask again", null));
        out.add(new Note<>(local(chair) + " gives its route back, keeping " + body + " (" + why + ")"));
    }

    /**
     * Walled in ({@link TrafficSettings.Rule#WALLED_IN}): a waiting chair whose way only idle
     * chairs block, none of which can be moved (every node they could go to is on its way, or held;
     * a full depot whose one way out the waiting chair stands on itself). After {@link #WALLED_MS}
     * its wait is answered FAILURE, naming the node in the way: the chair plans around it, and a
     * task it cannot reach so goes back to the Medical agent, which gives it to another chair (one
     * of those in the way, typically, which stands beside it). True if it was answered.
     */
    private boolean walledIn(String chair, Wait<T> w, List<String> in, long now, List<Outcome<T>> out) {
        if (!settings.on(TrafficSettings.Rule.WALLED_IN) || !in.stream().allMatch(h -> idle.contains(h) && !aside.containsKey(h))) {
            walledSince.remove(chair);
            return false;
        }
        long since = walledSince.computeIfAbsent(chair, c -> now);
        if (now - since < WALLED_MS) {
            return false;
        }
        walledSince.remove(chair);
        waiting.remove(chair);
        List<String> names = in.stream().map(Reservations::local).toList();
        int at = firstHeldBy(w.path(), in.get(0));
        Integer node = at < 0 ? null : at;
        out.add(new Failed<>(chair, w.ticket(), Failure.walledIn(names), node));
        out.add(new Note<>(local(chair) + " is walled in at node " + (node == null ? "?" : node) + " by idle " + names
                + " that none can move; its route " + w.path() + " is refused, for it to plan around"));
        return true;
    }

    /** Whether the chair still holds {@code node} and it is on its granted route past the first node of it the chair holds (where it is). */
    private boolean ahead(String chair, int node) {
        Route<T> r = routes.get(chair);
        if (r == null || !holds(chair, node)) {
            return false;
        }
        int at = -1;
        for (int i = 0; i < r.path.size(); i++) {
            if (at < 0 && holds(chair, r.path.get(i))) {
                at = i;
            }
            if (r.path.get(i) == node) {
                return at >= 0 && i > at;
            }
        }
        return false;
    }

    private int firstHeldBy(List<Integer> path, String chair) {
        for (int n : path) {
            if (holds(chair, n)) {
                return n;
            }
        }
        return -1;
    }

    /** Whether the chair holds any of the node (the node, or a lane of it). */
    private boolean holds(String chair, int node) {
        for (long k : held.getOrDefault(chair, List.of())) {
            if (node(k) == node) {
                return true;
            }
        }
        return false;
    }

    /**
     * A silent chair keeps where it stands: what it last said it stands on (a chair says so as it
     * sets off along each edge) and still holds, or else the first node it holds (it gives a node
     * back on reaching the next); the rest is given back.
     */
    private void silenced(String chair, List<Outcome<T>> out) {
        silent.add(chair);
        List<Long> mine = held.getOrDefault(chair, List.of());
        List<Integer> body = body(chair, mine.isEmpty() ? null : node(mine.get(0)));
        Wait<T> w = waiting.remove(chair);
        if (w != null) {
            out.add(new Failed<>(chair, w.ticket(), "silent for " + SILENT_MS / 1000 + " s", null));
        }
        keepOnly(chair, body);
        out.add(new Note<>(local(chair) + " is silent; it keeps " + body + " where it stands"));
    }

    /**
     * The nodes a chair's body takes: what it last said it stands on and still holds, or else
     * {@code fallback} (null: none).
     */
    private List<Integer> body(String chair, Integer fallback) {
        List<Integer> body = new ArrayList<>(standing.getOrDefault(chair, List.of()));
        body.removeIf(n -> !holds(chair, n));
        if (body.isEmpty() && fallback != null) {
            body.add(fallback);
        }
        return body;
    }

    /** Gives back every node the chair holds but {@code body}. */
    private void keepOnly(String chair, List<Integer> body) {
        for (long k : new ArrayList<>(held.getOrDefault(chair, List.of()))) {
            if (!body.contains(node(k))) {
                giveBack(chair, node(k));
            }
        }
    }

    /** A cycle of waits through {@code start}, or empty: each chair of it waits for a node the next holds. */
    private List<String> cycle(String start) {
        List<String> path = new ArrayList<>();
        return dfs(start, start, path, new HashSet<>()) ? path : List.of();
    }

    private boolean dfs(String start, String c, List<String> path, Set<String> seen) {
        path.add(c);
        for (String h : waitsFor(c)) {
            if (h.equals(start)) {
                return true;
            }
            if (seen.add(h) && dfs(start, h, path, seen)) {
                return true;
            }
        }
        path.remove(path.size() - 1);
        return false;
    }

    /**
     * Sends a chair to the nearest node that nobody holds and nobody's route needs, over nodes
     * nobody else holds, in a room only if {@code intoRooms}; prefers dead ends and parking places.
     * False if there is no such node now, or the chair is silent or was never heard (it could not be
     * told).
     */
    private boolean makeWay(String chair, String why, boolean intoRooms, List<Outcome<T>> out) {
        return makeWay(chair, why, intoRooms, out, null);
    }

    private boolean anyCycle() {
        return settings.on(TrafficSettings.Rule.ANY_CYCLE);
    }

    /**
     * As {@link #makeWay(String, String, boolean, List)}; with {@code onlyFor} not null, the node
     * need only be off the waiting routes of those chairs (the cycle it breaks, or the chair it is in
     * the way of) and off every granted route's end.
     */
    private boolean makeWay(String chair, String why, boolean intoRooms, List<Outcome<T>> out, Set<String> onlyFor) {
        List<Long> mine = held.get(chair);
        if (mine == null || mine.isEmpty() || !heard.containsKey(chair) || silent.contains(chair)) {
            return false;
        }
        int from = node(mine.get(0));
        Set<Integer> needed = needed(chair, onlyFor);
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
                if (!needed.contains(v) && (intoRooms || !map.inRoom(v))) {
                    int score = hops.get(v) + (map.edgesAt(v).size() == 1 || parking.contains(v) ? 0 : 2);
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
        Wait<T> own = waiting.remove(chair);
        if (own != null) {
            out.add(new Failed<>(chair, own.ticket(), "make-way", null));
        }
        idle.remove(chair);
        hold(chair, wholes(List.of(best)));
        aside.put(chair, best);
        asideSince.put(chair, clock);
        moves++;
        out.add(new MakeWay<>(chair, from, best, List.copyOf(path)));
        out.add(new Note<>(local(chair) + " makes way from node " + from + " to node " + best + " (" + why + ")"));
        return true;
    }

    /**
     * The nodes a chair sent aside must not end on: the waiting routes of the others (of those in
     * {@code onlyFor} only, and what is left of their granted routes, if not null), and every other
     * chair's destination.
     */
    private Set<Integer> needed(String chair, Set<String> onlyFor) {
        Set<Integer> needed = new HashSet<>();
        for (Wait<T> w : waiting.values()) {
            if (!w.chair().equals(chair) && (onlyFor == null || onlyFor.contains(w.chair()))) {
                needed.addAll(w.path());
            }
        }
        if (onlyFor != null) {
            // The cycle's granted chairs: what is left of their routes.
            routes.forEach((c, r) -> {
                if (onlyFor.contains(c) && !c.equals(chair)) {
                    needed.addAll(r.path);
                }
            });
        }
        goals.forEach((c, g) -> {
            if (!c.equals(chair)) {
                needed.add(g);
            }
        });
        return needed;
    }

    /**
     * Push ({@link TrafficSettings.Rule#PUSH}): {@code blocker}, idle in the way of
     * {@code forChair}, cannot make way: the free nodes it can reach are all needed, and the others
     * around them are held by idle chairs. The nearest of those (breadth first, the map's edges in
     * order) whose node is not needed and that can make way itself is sent aside; {@code blocker}
     * takes that node at a later review. With {@link TrafficSettings.Rule#PUSH_CHAIN} the search
     * goes on past idle chairs that cannot move either (a full depot: a row of parked chairs, the
     * free node beyond the last): the nearest that can is sent aside, and at each later review the
     * next one nearer the blocker takes the node freed, until the blocker can. False if none can.
     */
    private boolean push(String blocker, String forChair, List<Outcome<T>> out) {
        List<Long> mine = held.get(blocker);
        if (!settings.on(TrafficSettings.Rule.PUSH) || mine == null || mine.isEmpty() || rules != TrafficRules.IN_ORDER) {
            return false;
        }
        int from = node(mine.get(0));
        Set<Integer> needed = needed(blocker, null);
        Set<Integer> seen = new HashSet<>(List.of(from));
        ArrayDeque<Integer> q = new ArrayDeque<>(List.of(from));
        while (!q.isEmpty()) {
            int u = q.poll();
            for (Edge e : map.edgesAt(u)) {
                int v = e.other(u);
                if (!seen.add(v)) {
                    continue;
                }
                String h = otherHolder(blocker, v);
                if (h == null) {
                    q.add(v);   // free: the blocker (or, past a walled-in chair, that chair) can drive through it
                } else if (idle.contains(h) && !aside.containsKey(h) && !silent.contains(h)) {
                    String because = "it is idle in the way of " + local(blocker) + ", which is idle in the way of " + local(forChair);
                    if (!needed.contains(v) && (makeWay(h, because, false, out) || makeWay(h, because, true, out))) {
                        return true;
                    }
                    if (settings.on(TrafficSettings.Rule.PUSH_CHAIN)) {
                        q.add(v);   // walled in too: one farther on may move, and this one takes its node later
                    }
                }
            }
        }
        return false;
    }

    /** A chair other than {@code chair} that holds {@code node}, the first by name, or null. */
    private String otherHolder(String chair, int node) {
        String first = null;
        for (long k : whole(node)) {
            for (String h : holders.getOrDefault(k, Set.of())) {
                if (!h.equals(chair) && (first == null || h.compareTo(first) < 0)) {
                    first = h;
                }
            }
        }
        return first;
    }

    private boolean freeFor(String chair, int node) {
        return otherHolder(chair, node) == null;
    }

    static String local(String name) {
        int at = name.indexOf('@');
        return at < 0 ? name : name.substring(0, at);
    }
}
