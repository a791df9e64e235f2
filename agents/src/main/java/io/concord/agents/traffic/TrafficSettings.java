package io.concord.agents.traffic;

import java.util.EnumSet;
import java.util.Set;

/**
 * How a traffic agent keeps the fleet alive (docs/design.md, "Liveness"), fixed when the agent is
 * made: its traffic rules, the fleet monitor's limit, and its liveness rules, each of which a test
 * may switch off (on this agent alone, never globally) to show what it does.
 *
 * @param rules   how routes are reserved ({@link TrafficRules#IN_ORDER} by default)
 * @param stallMs how long a chair with work may make no progress (leave no node) before the
 *                monitor raises its alarm (and again at twice, four times it), in platform milliseconds
 * @param off     the liveness rules switched off (tests only; empty in every production path)
 */
public record TrafficSettings(TrafficRules rules, long stallMs, Set<Rule> off) {
    /** The fleet monitor's default limit: two minutes of hospital time. */
    public static final long STALL_MS = 120_000;

    /** The liveness rules (issue 47). */
    public enum Rule {
        /**
         * Every cycle of the wait-for graph is broken, whoever is in it: a chair sent aside that
         * has not got there within {@link Reservations#ASIDE_GRACE_MS} no longer shields its cycle,
         * and chairs under way give their grant back when no standing chair can step aside. Off:
         * a cycle with a chair sent aside in it is left alone, as before issue 47.
         */
        ANY_CYCLE,
        /**
         * Admission: no chair is cleared into a node it could not leave, that is a node whose next
         * node on its route is held, ahead of it, by a chair that will not drive on (it stands or
         * ends there). Such a chair waits a node back, and the wait is an edge of the wait-for graph.
         */
        ADMISSION,
        /** An idle chair off the map's parking places is sent to the nearest free one (hops, then the map's order). */
        HOME,
        /** The fleet monitor's alarm: a chair with work and no progress for {@link #stallMs()} is reported, and again at twice, four times it. */
        ALARM,
        /**
         * Push: an idle chair in the way that cannot make way, every free node around it needed or
         * walled in by other idle chairs, is cleared for by sending aside one of those whose node it
         * can then take (a depot of parked chairs, one of them on the exit).
         */
        PUSH,
        /**
         * Push goes on past idle chairs that are walled in too, to the nearest that can move (a full
         * depot: the chair on the exit leaves, and each one nearer the blocker takes the node freed).
         * Off: the search stops at the first idle chair on each way from the blocker.
         */
        PUSH_CHAIN,
        /**
         * A chair gives back only nodes it has left: a node ahead of it on its granted route that it
         * gives back stays its (a late answer to an order to make way there, which the traffic agent
         * sent before it had the chair's request for a route through that node; the chair, granted
         * that route meanwhile, refused the order). Off: the node is given back, and the next chair
         * in its queue may be cleared into it (head-on, if it comes the other way).
         */
        RELEASE_BEHIND,
        /**
         * A chair waiting for idle chairs that none can move (a full depot whose one way out it
         * stands on itself) has its wait refused after {@link Reservations#WALLED_MS}, naming the
         * node in the way: it plans around it, and a task it cannot reach goes to another chair.
         * Off: it waits for good.
         */
        WALLED_IN
    }

    public TrafficSettings {
        if (rules == null) {
            throw new IllegalArgumentException("traffic settings need rules");
        }
        if (stallMs <= 0) {
            throw new IllegalArgumentException("stallMs must be positive, got " + stallMs);
        }
        off = off.isEmpty() ? Set.of() : Set.copyOf(EnumSet.copyOf(off));
    }

    /** In order, every liveness rule on, the alarm after two minutes. */
    public static TrafficSettings standard() {
        return new TrafficSettings(TrafficRules.IN_ORDER, STALL_MS, Set.of());
    }

    /** These settings with other traffic rules. */
    public TrafficSettings withRules(TrafficRules rules) {
        return new TrafficSettings(rules, stallMs, off);
    }

    /** These settings with another limit for the alarm. */
    public TrafficSettings withStallMs(long ms) {
        return new TrafficSettings(rules, ms, off);
    }

    /** For tests: these settings with some liveness rules switched off. */
    public TrafficSettings without(Rule... rules) {
        EnumSet<Rule> o = off.isEmpty() ? EnumSet.noneOf(Rule.class) : EnumSet.copyOf(off);
        o.addAll(java.util.List.of(rules));
        return new TrafficSettings(this.rules, stallMs, o);
    }

    /** Whether the rule is on. */
    public boolean on(Rule rule) {
        return !off.contains(rule);
    }
}
