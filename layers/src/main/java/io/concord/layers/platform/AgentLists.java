package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.net.Address;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Predicate;

/**
 * The agent lists as one agent holds them: the Local Agent List of its host (from its container, or
 * its own if it is the container), the Global Agent List of the other hosts' agents, and the routes
 * both give: where an agent known only by name is reached. The lists are in name order, so that
 * pages and traces do not depend on hashing.
 */
final class AgentLists {
    /**
     * Where to send for a receiver: the address, and the agent whose node is there (the receiver
     * itself, or the agent that serves it: the container, for {@code df@platform}).
     */
    record Route(Address address, AID node) {
    }

    /**
     * Routes of agents that left the lists lately are kept this long: a list that flickers (an
     * agent taken for dead on a starved machine, a host's container changing) does not turn a
     * message to a known name into a FAILURE. After the grace the name is unknown.
     */
    static final long ROUTE_GRACE_NS = 5_000_000_000L;
    private static final int MAX_RECENT = 10_000;

    final TreeMap<String, AgentEntry> lal = new TreeMap<>();
    final TreeMap<String, AgentEntry> gal = new TreeMap<>();
    /** The GAL's version, and the agent it came from (this agent's container, or itself). */
    long gseq;
    String galFrom;
    private Map<String, Route> routes = new HashMap<>();
    private final LinkedHashMap<String, Route> recentRoutes = new LinkedHashMap<>(16, 0.75f, true);
    private final Map<String, Long> recentSince = new HashMap<>();

    /** The route to a listed agent, or to one that left less than the grace ago; else {@code null}. */
    Route route(String name, long nowNs) {
        Route r = routes.get(name);
        if (r != null) {
            return r;
        }
        r = recentRoutes.get(name);
        if (r != null) {
            Long since = recentSince.get(name);
            if (since != null && nowNs - since < ROUTE_GRACE_NS) {
                return r;
            }
            recentRoutes.remove(name);
            recentSince.remove(name);
        }
        return null;
    }

    /** The lists changed: the routes follow, and the old ones enter their grace. */
    void rebuildRoutes(long nowNs) {
        Map<String, Route> was = routes;
        routes = new HashMap<>(Math.max(16, was.size() * 4 / 3 + 1));
        for (AgentEntry e : gal.values()) {
            put(e);
        }
        for (AgentEntry e : lal.values()) {
            put(e);
        }
        // Only the routes that went: keeping every route of the lists in the grace map too cost
        // each agent two more maps of the whole list (at 5,000 agents, gigabytes in one JVM).
        for (Map.Entry<String, Route> e : was.entrySet()) {
            if (!routes.containsKey(e.getKey())) {
                recentRoutes.put(e.getKey(), e.getValue());
                recentSince.put(e.getKey(), nowNs);
            }
        }
        trimRecent();
    }

    /**
     * These names' entries changed (added, changed or removed, in either list): only their routes
     * follow, and a route that went enters its grace. A list change of a few entries then costs a
     * few routes, not the whole list's: with whole rebuilds, 1,000 agents joining one host cost
     * each member 1,000 rebuilds of 1,000 routes.
     */
    void updateRoutes(Collection<String> names, long nowNs) {
        for (String n : names) {
            AgentEntry e = lal.get(n);
            if (e == null) {
                e = gal.get(n);
            }
            Route old = routes.remove(n);
            if (e != null) {
                put(e);
            }
            if (old != null && !routes.containsKey(n)) {
                recentRoutes.put(n, old);
                recentSince.put(n, nowNs);
            }
        }
        trimRecent();
    }

    private void trimRecent() {
        while (recentRoutes.size() > MAX_RECENT) {
            String eldest = recentRoutes.keySet().iterator().next();
            recentRoutes.remove(eldest);
            recentSince.remove(eldest);
        }
    }

    private void put(AgentEntry e) {
        Route r = SHARED_ROUTES.get(e);
        if (r == null) {
            Address a = e.transportAddress();
            if (a == null) {
                return;
            }
            r = new Route(a, e.aid());
            if (SHARED_ROUTES.size() >= Lines.MAX_SHARED) {
                SHARED_ROUTES.clear();
            }
            SHARED_ROUTES.put(e, r);
        }
        routes.put(e.name(), r);
    }

    /** Routes shared by every agent of this JVM, as the entries are (see {@link Lines}); immutable. */
    private static final ConcurrentHashMap<AgentEntry, Route> SHARED_ROUTES =
            new ConcurrentHashMap<>();

    /**
     * What changed from {@code sent} to {@code now}, as a delta message carries it: the entries
     * removed first (their count returned), then those added or changed, into {@code out}.
     */
    static int diff(Map<String, AgentEntry> sent, Map<String, AgentEntry> now, List<AgentEntry> out) {
        int removed = 0;
        for (AgentEntry e : sent.values()) {
            if (!now.containsKey(e.name())) {
                out.add(e);
                removed++;
            }
        }
        for (AgentEntry e : now.values()) {
            if (!e.equals(sent.get(e.name()))) {
                out.add(e);
            }
        }
        return removed;
    }

    /**
     * Applies a delta's entries to a list: the first {@code removed} leave it, the others are put,
     * if {@code mayPut} lets them; returns the names touched, for their routes.
     */
    static List<String> apply(List<AgentEntry> changed, int removed, Map<String, AgentEntry> list,
                              Predicate<String> mayPut) {
        int r = Math.min(removed, changed.size());
        List<String> names = new ArrayList<>(changed.size());
        for (int i = 0; i < changed.size(); i++) {
            AgentEntry e = changed.get(i);
            names.add(e.name());
            if (i < r) {
                list.remove(e.name());
            } else if (mayPut.test(e.name())) {
                list.put(e.name(), e);
            }
        }
        return names;
    }

    /** Every agent this agent knows: the LAL, then the GAL's agents the LAL does not hold. */
    List<AgentEntry> all() {
        List<AgentEntry> all = new ArrayList<>(lal.values());
        for (AgentEntry e : gal.values()) {
            if (!lal.containsKey(e.name())) {
                all.add(e);
            }
        }
        return all;
    }

    /** The agent of that name, ignoring case (as FIPA names compare), in the LAL first. */
    AgentEntry findIgnoringCase(String name) {
        AgentEntry found = null;
        for (AgentEntry x : lal.values()) {
            if (x.name().equalsIgnoreCase(name)) {
                found = x;
            }
        }
        if (found == null) {
            for (AgentEntry x : gal.values()) {
                if (x.name().equalsIgnoreCase(name)) {
                    found = x;
                }
            }
        }
        return found;
    }

    /** The yellow pages in these lists: agents with a service matching each template (the DF's search, the one). */
    List<AgentEntry> search(List<ServiceDescription> templates) {
        List<AgentEntry> out = new ArrayList<>();
        for (AgentEntry e : all()) {
            if (ServiceDescription.offersAll(e.services(), templates)) {
                out.add(e);
            }
        }
        return out;
    }

    /** The entries' lines packed into as few pages as fit in {@code maxBytes} each (at least one page). */
    static List<String> pages(Collection<AgentEntry> entries, int maxBytes) {
        List<String> out = new ArrayList<>();
        StringBuilder b = new StringBuilder();
        for (AgentEntry e : entries) {
            StringBuilder line = new StringBuilder(80);
            Lines.appendEntry(line, e);
            if (b.length() > 0 && b.length() + line.length() + 1 > maxBytes) {
                out.add(b.toString());
                b.setLength(0);
            }
            if (b.length() > 0) {
                b.append('\n');
            }
            b.append(line);
        }
        out.add(b.toString());
        return out;
    }
}
