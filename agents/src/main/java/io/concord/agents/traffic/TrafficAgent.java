package io.concord.agents.traffic;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.Content;
import io.concord.agents.proto.Services;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.TickerBehaviour;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

/**
 * Keeps chairs apart on the map's route graph: a chair drives a route only once it holds every
 * node of it, and gives back each node as it leaves it. The rules are {@link Reservations}'s (why
 * whole routes, who is moved out of the way, what a silent chair keeps); this agent speaks them.
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
    public static final long SILENT_MS = Reservations.SILENT_MS;
    private static final long REVIEW_MS = 1_000;

    private final HospitalMap map;
    private final Consumer<String> log;
    private final Reservations<AclMessage> rules;
    private final Map<String, AID> aids = new HashMap<>();

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
        this.rules = new Reservations<>(map, rules);
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
                tell(rules.review(currentTimeMillis()));
            }
        });
    }

    // ---- what it can tell (tests, console) ------------------------------------------------------

    /** Who holds which node. */
    public Map<Integer, Set<String>> holders() {
        return rules.holders();
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

    /** Deadlocks found (each broken by moving a chair of it). */
    public long deadlocks() {
        return rules.deadlocks();
    }

    // ---- messages -------------------------------------------------------------------------------

    private void handle(AclMessage m) {
        Content c = Content.parseOrAnswer(m, this::send);
        if (c == null) {
            return;
        }
        String chair = m.getSender().name();
        aids.put(chair, m.getSender());
        long now = currentTimeMillis();
        tell(rules.heard(chair, now));
        try {
            switch (c.verb()) {
                case "reserve" -> tell(rules.reserve(chair, m, nodes(c, "at"), nodes(c, "path"), "true".equals(c.get("aside")), now));
                case "release" -> tell(rules.release(chair, c.integer("node"), now));
                case "idle" -> tell(rules.idle(chair, nodes(c, "at"), now));
                case "here" -> {
                    if (c.get("at") != null) {
                        rules.standing(chair, nodes(c, "at"));
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

    /** Tells the chairs what the rules decided, in order. */
    private void tell(List<Reservations.Outcome<AclMessage>> outcomes) {
        for (Reservations.Outcome<AclMessage> o : outcomes) {
            if (o instanceof Reservations.Granted<AclMessage> g) {
                send(g.ticket().createReply().setPerformative(Performative.INFORM)
                        .setContent(Content.of("granted").with("path", join(g.path())).toString()));
            } else if (o instanceof Reservations.Waiting<AclMessage> w) {
                send(w.ticket().createReply().setPerformative(Performative.AGREE)
                        .setContent(Content.of("reserve").with("held-by", String.join(",", w.heldBy())).toString()));
            } else if (o instanceof Reservations.Failed<AclMessage> f) {
                Content why = Content.of("failure");
                if (f.node() != null) {
                    why = why.with("node", f.node());
                }
                send(f.ticket().createReply().setPerformative(Performative.FAILURE).setContent(why.with("reason", f.reason()).toString()));
            } else if (o instanceof Reservations.MakeWay<AclMessage> mw) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(aids.get(mw.chair()));
                m.setOntology(Services.ONTOLOGY);
                m.setContent(Content.of("make-way").with("from", mw.from()).with("to", mw.to()).with("path", join(mw.path())).toString());
                send(m);
            } else if (o instanceof Reservations.Note<AclMessage> n) {
                log.accept(getLocalName() + ": " + n.text());
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

    private static String join(List<Integer> nodes) {
        StringBuilder b = new StringBuilder();
        for (int n : nodes) {
            b.append(b.length() == 0 ? "" : ",").append(n);
        }
        return b.toString();
    }
}
