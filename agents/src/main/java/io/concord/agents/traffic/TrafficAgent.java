package io.concord.agents.traffic;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Clear;
import io.concord.agents.proto.WheelchairMessage.Failure;
import io.concord.agents.proto.WheelchairMessage.Granted;
import io.concord.agents.proto.WheelchairMessage.Here;
import io.concord.agents.proto.WheelchairMessage.Idle;
import io.concord.agents.proto.WheelchairMessage.MakeWay;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.agents.proto.WheelchairMessage.Release;
import io.concord.agents.proto.WheelchairMessage.Reserve;
import io.concord.agents.proto.WheelchairMessage.ReserveWaits;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.TickerBehaviour;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Keeps chairs apart on the map's route graph: a chair reserves its route, drives into a node only
 * when it is first in that node's queue, and gives back each node as it leaves it. The rules are
 * {@link Reservations}'s (the queues, who is moved out of the way, what a silent chair keeps); this
 * agent speaks them.
 *
 * <p>Messages (ontology {@code concord-wheelchair}), from a chair's control agent:
 * <ul>
 *   <li>REQUEST {@code reserve} (the nodes it stands on, the route, whether it steps aside): it gives
 *       back everything but {@code at}, and is granted the route (INFORM {@code granted}, with {@code :upto}: how far it may drive now) at once or later, with an AGREE naming who is in the way
 *       meanwhile; then INFORM {@code clear} in the same conversation each time the chairs
 *       ahead let it drive farther. A route that is not on the map is REFUSEd. A wait that cannot
 *       end (a silent chair stands on the route, or ahead of it) gets a FAILURE with the reason.</li>
 *   <li>INFORM {@code release}: it has left the node.</li>
 *   <li>INFORM {@code idle}: it has nothing to do, standing at {@code at}.</li>
 *   <li>INFORM {@code here} (with {@code :at}, the nodes): it is alive (its holds are kept), standing on those
 *       nodes; a chair says so as it sets off along each edge, so that a chair that falls silent
 *       keeps exactly the nodes its body takes.</li>
 * </ul>
 * To a chair: INFORM {@code make-way}: drive to {@code to} (held for it) and ask again
 * from there; its pending wait, if any, is answered FAILURE {@code make-way}.
 */
public class TrafficAgent extends Agent {
    /** A chair not heard of for this long keeps only the node it stands on; who waits for that node is told. */
    public static final long SILENT_MS = Reservations.SILENT_MS;
    private static final long REVIEW_MS = 1_000;

    private final HospitalMap map;
    private final Consumer<String> log;
    private final Reservations<AclMessage> rules;
    private final Map<String, AID> aids = new HashMap<>();
    /** Wall time of the last decisions (each call of the rules), for the operator and the benchmark; no rule reads it. */
    private final long[] decisionNs = new long[1 << 12];
    private long decisions;

    /**
     * @param map the route graph it reserves
     * @param log told of every chair moved out of the way and every silent chair
     */
    public TrafficAgent(HospitalMap map, Consumer<String> log) {
        this(map, log, TrafficRules.IN_ORDER);
    }

    /**
     * With other rules: {@link TrafficRules#WHOLE_ROUTES} to compare with, {@link TrafficRules#NONE}
     * only in tests (every route granted at once; the chairs keep apart by their range sensors
     * alone), to show what the reservations do. Fixed at construction: nothing can switch a running
     * traffic agent's rules.
     */
    public TrafficAgent(HospitalMap map, Consumer<String> log, TrafficRules rules) {
        this(map, log, TrafficSettings.standard().withRules(rules));
    }

    /**
     * With liveness settings: the fleet monitor's limit, and (tests only) liveness rules switched
     * off on this agent. Fixed at construction.
     */
    public TrafficAgent(HospitalMap map, Consumer<String> log, TrafficSettings settings) {
        this.map = map;
        this.log = log;
        this.rules = new Reservations<>(map, settings);
    }

    @Override
    protected void setup() {
        Platform.of(this).register(ServiceDescription.of(Services.TRAFFIC, getLocalName()));
        MessageTemplate mine = MessageTemplate.matchOntology(Services.ONTOLOGY).and(
                MessageTemplate.matchPerformative(Performative.REQUEST).or(MessageTemplate.matchPerformative(Performative.INFORM))
                        .or(MessageTemplate.matchPerformative(Performative.QUERY_REF)));
        Inbox.each(this, mine, this::handle);
        addBehaviour(new TickerBehaviour(this, REVIEW_MS) {
            @Override
            protected void onTick() {
                long now = currentTimeMillis();
                tell(timed(() -> rules.review(now)));
            }
        });
    }

    // ---- what it can tell (tests, console) ------------------------------------------------------

    /** Who holds which node, in each node's queue order (the first may be on it). */
    public Map<Integer, List<String>> holders() {
        return rules.holders();
    }

    /** For each node with lanes somebody holds: its two lanes' queues, lane 0 first (see {@code HospitalMap.laneAxis}). */
    public Map<Integer, List<List<String>>> lanes() {
        return rules.lanes();
    }

    /** Each chair's granted route, up to where it may drive now. */
    public Map<String, List<Integer>> cleared() {
        return rules.cleared();
    }

    /** Who waits for which route, and who is in the way. */
    public List<String> waits() {
        return rules.waits();
    }

    /** Routes granted so far. */
    public long grants() {
        return rules.grants();
    }

    /** Chairs moved out of the way so far (idle ones in the way and deadlocks broken). */
    public long moves() {
        return rules.moves();
    }

    /** Deadlocks broken (by moving a chair of each aside, or taking a grant back). */
    public long deadlocks() {
        return rules.deadlocks();
    }

    /** Alarms the fleet monitor has raised (a chair with work and no progress for the limit). */
    public long alarms() {
        return rules.alarms();
    }

    /** The fleet monitor's view: for each chair with work, when (platform time) it last made progress. */
    public Map<String, Long> lastProgress() {
        return rules.lastProgress();
    }

    /** Reviews (one a second at most) that found a deadlock nobody could break then: see {@code Reservations}. */
    public long deadlockReviewsUnbroken() {
        return rules.deadlockReviewsUnbroken();
    }

    // ---- messages -------------------------------------------------------------------------------

    private void handle(AclMessage m) {
        try {
            WheelchairMessage.dispatch(m, handler, this::send);
        } catch (IllegalArgumentException e) {
            // a route off the map
            if (m.getPerformative() == Performative.REQUEST || m.getPerformative() == Performative.QUERY_REF) {
                send(m.createReply().setPerformative(Performative.REFUSE).setContent(Refused.because(e.getMessage()).encode()));
            }
        }
    }

    /** What a chair says; every word counts as a sign of life. */
    private final WheelchairMessage.Handler handler = new WheelchairMessage.Handler() {
        @Override
        public void onReserve(Reserve r, AclMessage m) {
            long now = heard(m);
            List<Integer> at = onMap("at", r.at());
            List<Integer> path = onMap("path", r.path());
            tell(timed(() -> rules.reserve(m.getSender().name(), m, at, path, r.aside(), now)));
        }

        @Override
        public void onWaitEstimate(WheelchairMessage.WaitEstimate w, AclMessage m) {
            if (m.getPerformative() != Performative.QUERY_REF) {
                return;
            }
            heard(m);
            List<Integer> path = onMap("path", w.path());
            double s = rules.expectedWaitS(m.getSender().name(), path);
            send(m.createReply().setPerformative(Performative.INFORM_REF)
                    .setContent(new WheelchairMessage.WaitEstimate(path, Math.round(s * 10) / 10.0).encode()));
        }

        @Override
        public void onRelease(Release r, AclMessage m) {
            long now = heard(m);
            tell(timed(() -> rules.release(m.getSender().name(), r.node(), now)));
        }

        @Override
        public void onIdle(Idle i, AclMessage m) {
            long now = heard(m);
            List<Integer> at = onMap("at", i.at());
            tell(timed(() -> rules.idle(m.getSender().name(), at, now)));
        }

        @Override
        public void onHere(Here h, AclMessage m) {
            heard(m);
            if (h.at() != null) {
                rules.standing(m.getSender().name(), onMap("at", h.at()));
            }
        }

        @Override
        public void unknown(String verb, AclMessage m) {
            heard(m);
            if (m.getPerformative() == Performative.REQUEST) {
                send(m.createReply().setPerformative(Performative.NOT_UNDERSTOOD).setContent("unknown request '" + verb + "'; the traffic agent takes reserve (and is told release, idle, here; docs/wheelchair-protocol.md)"));
            }
        }
    };

    /** The chair has said something: its holds are kept. Returns the time now. */
    private long heard(AclMessage m) {
        String chair = m.getSender().name();
        aids.put(chair, m.getSender());
        long now = currentTimeMillis();
        tell(rules.heard(chair, now));
        return now;
    }

    /** Up to the last 4,096 decisions' wall times (one call of the rules each: a request, a release, a review), in ns. */
    public long[] decisionTimesNs() {
        int n = (int) Math.min(decisions, decisionNs.length);
        return java.util.Arrays.copyOf(decisionNs, n);
    }

    /** Decisions taken so far. */
    public long decisions() {
        return decisions;
    }

    private List<Reservations.Outcome<AclMessage>> timed(java.util.function.Supplier<List<Reservations.Outcome<AclMessage>>> call) {
        long t0 = System.nanoTime();
        List<Reservations.Outcome<AclMessage>> out = call.get();
        decisionNs[(int) (decisions++ & (decisionNs.length - 1))] = System.nanoTime() - t0;
        return out;
    }

    /** Tells the chairs what the rules decided, in order. */
    private void tell(List<Reservations.Outcome<AclMessage>> outcomes) {
        for (Reservations.Outcome<AclMessage> o : outcomes) {
            if (o instanceof Reservations.Granted<AclMessage> g) {
                send(g.ticket().createReply().setPerformative(Performative.INFORM).setContent(new Granted(g.path(), g.upto()).encode()));
            } else if (o instanceof Reservations.Clear<AclMessage> c) {
                send(c.ticket().createReply().setPerformative(Performative.INFORM).setContent(new Clear(c.upto()).encode()));
            } else if (o instanceof Reservations.Waiting<AclMessage> w) {
                send(w.ticket().createReply().setPerformative(Performative.AGREE).setContent(new ReserveWaits(w.heldBy()).encode()));
            } else if (o instanceof Reservations.Failed<AclMessage> f) {
                send(f.ticket().createReply().setPerformative(Performative.FAILURE).setContent(
                        new Failure(null, f.node(), f.reason()).encode()));
            } else if (o instanceof Reservations.MakeWay<AclMessage> mw) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(aids.get(mw.chair()));
                m.setOntology(Services.ONTOLOGY);
                m.setLanguage(Services.LANGUAGE);
                m.setContent(new MakeWay(mw.from(), mw.to(), mw.path()).encode());
                send(m);
            } else if (o instanceof Reservations.Note<AclMessage> n) {
                log.accept(getLocalName() + ": " + n.text());
            } else if (o instanceof Reservations.Stalled<AclMessage> st) {
                alarm(st);
            }
        }
    }

    /** The fleet monitor's alarm: in the log, and to every Medical agent in the yellow pages. */
    private void alarm(Reservations.Stalled<AclMessage> st) {
        long seconds = st.forMs() / 1000;
        log.accept(getLocalName() + ": ALARM " + Reservations.local(st.chair()) + " has made no progress for " + seconds
                + " s; it waits for " + st.waitsFor());
        for (io.concord.layers.platform.AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.ofType(Services.MEDICAL))) {
            AID to = e.aid();
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(to);
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(new WheelchairMessage.Stalled(st.chair(), seconds, st.waitsFor()).encode());
            send(m);
        }
    }

    /** The nodes, each checked to be on the map. */
    private List<Integer> onMap(String key, List<Integer> nodes) {
        for (int n : nodes) {
            if (!map.hasNode(n)) {
                throw new IllegalArgumentException(key + ": there is no node " + n + " on " + map.name());
            }
        }
        return nodes;
    }
}
