package io.concord.agents.control;

import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Clear;
import io.concord.agents.proto.WheelchairMessage.Failure;
import io.concord.agents.proto.WheelchairMessage.Granted;
import io.concord.agents.proto.WheelchairMessage.Here;
import io.concord.agents.proto.WheelchairMessage.Idle;
import io.concord.agents.proto.WheelchairMessage.Release;
import io.concord.agents.proto.WheelchairMessage.Reserve;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.proto.FipaProtocols;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.BiConsumer;

/**
 * A control agent's side of the traffic agent (see {@code TrafficAgent}): before it drives a
 * route it asks for all of it, and drives once granted, into each node only as far as it is told
 * it may ({@code upto}, moved on by {@code clear}); it gives back each node it leaves, says
 * when it is idle and where, and that it is alive. With no traffic agent in the yellow pages
 * every route may be driven at once (one chair alone needs none). No transport of its own: it
 * speaks through a {@link Port}, which the agent implements over its yellow pages and its asks.
 */
final class TrafficClient {
    /** How long a reservation may wait before it is asked again. */
    static final long WAIT_MS = 1_800_000;

    /** How a traffic client reaches the traffic agent. */
    interface Port extends Outbox {
        /** The traffic agent, from the yellow pages, or null if there is none. */
        AID trafficAgent();
    }

    private final Port port;
    /** Told of a route that cannot be granted: the node in the way and why. */
    private final BiConsumer<Integer, String> onRefused;
    private final Set<Integer> held = new LinkedHashSet<>();
    private List<Integer> granted;
    /** How far along {@link #granted} it may drive (an index into it). */
    private int clearTo;
    /** The conversation of the granted reservation (a {@code clear} or a late FAILURE comes in it). */
    private String grantedIn;
    private List<Integer> asked;
    /** The request of {@link #asked} (its conversation is the grant's to come). */
    private AclMessage askedBy;
    /**
     * A {@code clear} in the conversation asked that came before its grant (both come at once, and
     * the clear may be read first), or null: applied when the grant comes. Dropped, the chair would
     * wait for ever at the grant's {@code upto} for a clear it had already been sent.
     */
    private Integer earlyClear;
    private long seq;
    private int idleAt = -1;

    TrafficClient(Port port, BiConsumer<Integer, String> onRefused) {
        this.port = port;
        this.onRefused = onRefused;
    }

    private AID traffic() {
        return port.trafficAgent();
    }

    /**
     * True if the chair may drive {@code route} (this very list): granted, or no traffic agent.
     * Otherwise asks for it once, from where the chair stands ({@code at}), and answers false
     * until the grant comes.
     */
    boolean mayDrive(List<Integer> route, List<Integer> at, boolean aside) {
        if (route == granted) {
            return true;
        }
        AID traffic = traffic();
        if (traffic == null) {
            return true;
        }
        if (route == asked) {
            return false;
        }
        asked = route;
        idleAt = -1;
        long mine = ++seq;
        held.clear();
        held.addAll(at);
        AclMessage req = new AclMessage(Performative.REQUEST);
        req.addReceiver(traffic);
        req.setProtocol(FipaProtocols.REQUEST);
        req.setOntology(Services.ONTOLOGY);
        req.setLanguage(Services.LANGUAGE);
        req.setContent(new Reserve(at, route, aside).encode());
        askedBy = req;
        earlyClear = null;
        port.ask(req, WAIT_MS).thenAccept(a -> {
            if (seq != mine) {
                return;
            }
            asked = null;
            askedBy = null;
            Integer early = earlyClear;
            earlyClear = null;
            if (a == null) {
                return; // asked again on the next reading
            }
            if (a.getPerformative() == Performative.INFORM) {
                granted = route;
                grantedIn = a.getConversationId();
                Integer upto = WheelchairMessage.tryDecode(a).map(w -> w instanceof Granted g ? g.upto() : null).orElse(null);
                clearTo = upto == null ? route.size() - 1 : Math.max(0, route.indexOf(upto));
                if (early != null && route.indexOf(early) > clearTo) {
                    clearTo = route.indexOf(early);
                }
                held.addAll(route);
                return;
            }
            String why = WheelchairMessage.reasonOf(a);
            if (why == null) {
                why = "";
            } else if (why.equals("make-way") || why.startsWith("superseded")) {
                return;
            }
            onRefused.accept(failedAt(a), a.getPerformative() + ": " + why);
        });
        return false;
    }

    /**
     * True if the chair may drive on to node {@code index} of {@code route} (this very list): it is
     * granted that far, or needs no grant.
     */
    boolean mayGoOn(List<Integer> route, int index) {
        return traffic() == null || route != granted || index <= clearTo;
    }

    /** The node of the granted route it may not drive into yet, or -1. */
    int waitsAt() {
        return granted != null && clearTo + 1 < granted.size() ? granted.get(clearTo + 1) : -1;
    }

    /** Whether {@code m} belongs to the granted reservation's conversation (a {@code clear}, or a FAILURE after the grant). */
    boolean isAboutGrant(AclMessage m) {
        return grantedIn != null && grantedIn.equals(m.getConversationId());
    }

    /**
     * A message in the granted reservation's conversation: {@code clear} lets the chair drive
     * farther; a FAILURE (the chair ahead fell silent, or a deadlock took the grant back) ends the
     * grant, and the chair plans again. A {@code clear} in the conversation of the route asked,
     * read before its grant, is kept for that grant.
     */
    void aboutGrant(AclMessage m) {
        if (!isAboutGrant(m)) {
            if (askedBy != null && m.getConversationId() != null && m.getConversationId().equals(askedBy.getConversationId())
                    && m.getPerformative() == Performative.INFORM) {
                WheelchairMessage.tryDecode(m).ifPresent(w -> {
                    if (w instanceof Clear c && asked != null && (earlyClear == null || asked.indexOf(c.upto()) > asked.indexOf(earlyClear))) {
                        earlyClear = c.upto();
                    }
                });
            }
            return;
        }
        if (m.getPerformative() == Performative.INFORM) {
            WheelchairMessage.tryDecode(m).ifPresent(w -> {
                if (w instanceof Clear c && granted != null) {
                    int i = granted.indexOf(c.upto());
                    if (i > clearTo) {
                        clearTo = i;
                    }
                }
            });
            return;
        }
        if (m.getPerformative() == Performative.FAILURE) {
            String why = WheelchairMessage.reasonOf(m);
            reset();
            onRefused.accept(failedAt(m), "FAILURE: " + (why == null ? "" : why));
        }
    }

    /** The node a FAILURE of the traffic agent names (where the route is stuck), or -1. */
    private static int failedAt(AclMessage m) {
        return WheelchairMessage.tryDecode(m).map(w -> w instanceof Failure f && f.node() != null ? f.node() : -1).orElse(-1);
    }

    /** True if {@code route} (this very list) is granted or needs no grant. */
    boolean mayDriveNow(List<Integer> route) {
        return route == granted || traffic() == null;
    }

    /** Forgets any grant and question (a step aside ordered, a task cancelled): the next route is asked anew. */
    void reset() {
        seq++;
        granted = null;
        grantedIn = null;
        asked = null;
        askedBy = null;
        earlyClear = null;
        idleAt = -1;
    }

    /** The chair has reached a node of its route: gives back every node not in {@code still} (the route's rest). */
    void keepOnly(List<Integer> still) {
        AID traffic = traffic();
        for (int n : new ArrayList<>(held)) {
            if (!still.contains(n)) {
                held.remove(n);
                if (traffic != null) {
                    inform(traffic, new Release(n));
                }
            }
        }
    }

    /** Whether the route asked for or granted last takes {@code node} (a node the chair drives into, or drove through). */
    boolean onRoute(int node) {
        return (granted != null && granted.contains(node)) || (asked != null && asked.contains(node));
    }

    /** Gives back one node the chair was given and will not use. */
    void release(int node) {
        held.remove(node);
        AID traffic = traffic();
        if (traffic != null) {
            inform(traffic, new Release(node));
        }
    }

    /** The chair has nothing to do at {@code node}: said once until it asks for a route again. */
    void idle(int node) {
        if (idleAt == node) {
            return;
        }
        AID traffic = traffic();
        if (traffic == null) {
            return;
        }
        reset();
        idleAt = node;
        held.clear();
        held.add(node);
        inform(traffic, new Idle(List.of(node)));
    }

    /** The chair is alive and stands on {@code at} (a silent chair keeps only where it stands). */
    void alive(List<Integer> at) {
        AID traffic = traffic();
        if (traffic != null) {
            inform(traffic, new Here(null, at));
        }
    }

    /** The nodes it holds, where it stands first. */
    List<Integer> held() {
        return List.copyOf(held);
    }

    private void inform(AID traffic, WheelchairMessage w) {
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addReceiver(traffic);
        m.setOntology(Services.ONTOLOGY);
        m.setLanguage(Services.LANGUAGE);
        m.setContent(w.encode());
        port.send(m);
    }
}
