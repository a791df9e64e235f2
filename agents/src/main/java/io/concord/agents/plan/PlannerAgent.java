package io.concord.agents.plan;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.Asks;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Blocked;
import io.concord.agents.proto.WheelchairMessage.DoorState;
import io.concord.agents.proto.WheelchairMessage.NoRoute;
import io.concord.agents.proto.WheelchairMessage.PassRequest;
import io.concord.agents.proto.WheelchairMessage.Plan;
import io.concord.agents.proto.WheelchairMessage.PlanAgreed;
import io.concord.agents.proto.WheelchairMessage.PlanRequest;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.agents.proto.WheelchairMessage.StateQuery;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.TickerBehaviour;
import io.concord.core.proto.Conversations;
import io.concord.layers.Platform;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * The cognitive agent, one per chair: plans routes with A* on the map's graph, and gives out only
 * plans that every door on them confirmed for the chair.
 *
 * <ul>
 *   <li>REQUEST {@code plan-request}: REFUSE (unknown node), or AGREE and then
 *       INFORM-REF {@code plan} or FAILURE
 *       {@code no-route}.</li>
 *   <li>It finds the doors in the DF and subscribes to each (position and state); an OFFLINE door
 *       is planned around. Before giving a plan out it asks every door on it to let the chair
 *       pass (REQUEST {@code pass}); a door that refuses is planned around, up to three times.</li>
 *   <li>INFORM {@code blocked} from its chair: that edge is avoided for a minute.</li>
 * </ul>
 */
public class PlannerAgent extends Agent {
    /** A door as the planner knows it. */
    public record KnownDoor(String id, AID agent, String state) {
    }

    private static final long BLOCKED_MS = 60_000;
    private static final int ATTEMPTS = 3;
    private static final double DOOR_PENALTY_M = 4;

    private final HospitalMap map;
    private final String chair;
    private final Consumer<String> log;
    private final AStar astar;
    private final Map<String, KnownDoor> doors = new LinkedHashMap<>();
    private final Map<String, Long> blocked = new HashMap<>();
    private Asks asks;

    /**
     * @param map   the map to plan on
     * @param chair the name of the control agent it plans for (its yellow-pages property)
     * @param log   told of every plan given out and refused
     */
    public PlannerAgent(HospitalMap map, String chair, Consumer<String> log) {
        this.map = map;
        this.chair = chair;
        this.log = log;
        this.astar = new AStar(RouteGraph.of(map), DOOR_PENALTY_M);
    }

    @Override
    protected void setup() {
        Platform.of(this).register(ServiceDescription.of(Services.PLANNER, getLocalName()).withProperty("chair", chair));
        asks = new Asks(this);
        addBehaviour(asks);
        addBehaviour(new TickerBehaviour(this, 1_000) {
            @Override
            protected void onTick() {
                discoverDoors();
            }
        });
        discoverDoors();
        MessageTemplate mine = MessageTemplate.matchPerformative(Performative.REQUEST).or(WheelchairMessage.matching(Blocked.class));
        Inbox.each(this, mine, m -> WheelchairMessage.dispatch(m, handler, this::send));
    }

    /** The doors it knows, with their last state. */
    public List<KnownDoor> knownDoors() {
        return new ArrayList<>(doors.values());
    }

    private void discoverDoors() {
        for (AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.ofType(Services.DOOR))) {
            for (ServiceDescription s : e.services()) {
                if (!s.type().equals(Services.DOOR) || doors.containsKey(s.name())) {
                    continue;
                }
                String id = s.name();
                AID agent = e.aid();
                doors.put(id, new KnownDoor(id, agent, "unknown"));
                AclMessage sub = new AclMessage(Performative.SUBSCRIBE);
                sub.addReceiver(agent);
                sub.setProtocol("fipa-subscribe");
                sub.setOntology(Services.ONTOLOGY);
                sub.setLanguage(Services.LANGUAGE);
                sub.setContent(new StateQuery().encode());
                var handle = Conversations.subscribe(this, sub, n -> update(id, agent, n));
                handle.agreed().thenAccept(agree -> update(id, agent, agree));
            }
        }
    }

    private void update(String id, AID agent, AclMessage m) {
        try {
            doors.put(id, new KnownDoor(id, agent, WheelchairMessage.decode(m, DoorState.class).state()));
        } catch (IllegalArgumentException e) {
            // a door that says something else keeps its last state
        }
    }

    private final WheelchairMessage.Handler handler = new WheelchairMessage.Handler() {
        @Override
        public void onBlocked(Blocked b, AclMessage m) {
            String key = AStar.edgeKey(b.from(), b.to());
            blocked.put(key, currentTimeMillis() + BLOCKED_MS);
            log.accept(getLocalName() + ": edge " + key + " blocked, planned around for " + BLOCKED_MS / 1000 + " s");
        }

        @Override
        public void onPlanRequest(PlanRequest p, AclMessage m) {
            for (int n : new int[] {p.from(), p.to()}) {
                if (!map.hasNode(n)) {
                    send(m.createReply().setPerformative(Performative.REFUSE).setContent(
                            new Refused(p.task(), null, "unknown node " + n, false).encode()));
                    return;
                }
            }
            send(m.createReply().setPerformative(Performative.AGREE).setContent(new PlanAgreed(p.task()).encode()));
            String forChair = p.chair() != null ? p.chair() : m.getSender().name();
            if (p.via() != null) {
                along(m, p.task(), p.via(), forChair);
                return;
            }
            plan(m, p.task(), p.from(), p.to(), forChair, new HashSet<>(), ATTEMPTS);
        }

        @Override
        public void unknown(String verb, AclMessage m) {
            if (m.getPerformative() == Performative.REQUEST) {
                send(m.createReply().setPerformative(Performative.NOT_UNDERSTOOD).setContent("unknown request '" + verb + "'; a planner takes plan-request (docs/wheelchair-protocol.md)"));
            }
        }
    };

    /** The way the chair was told to take (its doors asked, no other way sought), or FAILURE if it is not on the map or a door refuses. */
    private void along(AclMessage request, String task, List<Integer> via, String forChair) {
        List<String> onWay = new ArrayList<>();
        double length = 0;
        for (int i = 1; i < via.size(); i++) {
            var e = map.edge(via.get(i - 1), via.get(i));
            if (e.isEmpty()) {
                send(request.createReply().setPerformative(Performative.FAILURE).setContent(
                        new NoRoute(task, "via: no edge " + via.get(i - 1) + "-" + via.get(i) + " on " + map.name()).encode()));
                return;
            }
            length += e.get().length(map);
            if (e.get().door() != null) {
                if (!doorUsable(e.get().door())) {
                    send(request.createReply().setPerformative(Performative.FAILURE).setContent(
                            new NoRoute(task, "via: door " + e.get().door() + " is offline or unknown").encode()));
                    return;
                }
                onWay.add(e.get().door());
            }
        }
        Route r = new Route(via, onWay, length);
        confirm(request, task, r, forChair, refusedAll -> send(request.createReply().setPerformative(Performative.FAILURE).setContent(
                new NoRoute(task, "doors " + refusedAll + " refused the chair on the way " + via).encode())));
    }

    private void plan(AclMessage request, String task, int from, int to, String forChair, Set<String> refused, int attempts) {
        long now = currentTimeMillis();
        blocked.values().removeIf(until -> until <= now);
        Route r = astar.find(from, to, blocked.keySet(), d -> !refused.contains(d) && doorUsable(d));
        if (r == null) {
            String why = "no route from " + from + " to " + to + (refused.isEmpty() ? "" : " avoiding doors " + refused)
                    + (blocked.isEmpty() ? "" : " and blocked edges " + blocked.keySet());
            log.accept(getLocalName() + ": " + task + " " + why);
            send(request.createReply().setPerformative(Performative.FAILURE).setContent(new NoRoute(task, why).encode()));
            return;
        }
        confirm(request, task, r, forChair, now2 -> {
            if (attempts > 1) {
                Set<String> all = new HashSet<>(refused);
                all.addAll(now2);
                plan(request, task, from, to, forChair, all, attempts - 1);
            } else {
                Set<String> all = new HashSet<>(refused);
                all.addAll(now2);
                send(request.createReply().setPerformative(Performative.FAILURE).setContent(
                        new NoRoute(task, "doors " + all + " refused the chair").encode()));
            }
        });
    }

    /** Asks every door on {@code r} to let the chair pass: gives the plan if all confirm, else tells {@code refusedBy} which did not. */
    private void confirm(AclMessage request, String task, Route r, String forChair, Consumer<Set<String>> refusedBy) {
        List<CompletableFuture<AclMessage>> answers = new ArrayList<>();
        for (String d : r.doors()) {
            KnownDoor k = doors.get(d);
            AclMessage ask = new AclMessage(Performative.REQUEST);
            ask.addReceiver(k.agent());
            ask.setProtocol("fipa-request");
            ask.setOntology(Services.ONTOLOGY);
            ask.setLanguage(Services.LANGUAGE);
            ask.setContent(new PassRequest(forChair, task).encode());
            answers.add(asks.ask(ask, 2_000, null));
        }
        CompletableFuture.allOf(answers.toArray(new CompletableFuture[0])).thenRun(() -> {
            Set<String> no = new HashSet<>();
            for (int i = 0; i < answers.size(); i++) {
                AclMessage a = answers.get(i).join();
                if (a == null || a.getPerformative() != Performative.CONFIRM) {
                    no.add(r.doors().get(i));
                }
            }
            if (no.isEmpty()) {
                log.accept(getLocalName() + ": " + task + " plan " + r.nodes() + " through " + r.doors() + " confirmed");
                AclMessage inform = request.createReply().setPerformative(Performative.INFORM_REF);
                inform.setContent(new Plan(task, r.nodes(), r.doors(), r.lengthM()).encode());
                send(inform);
            } else {
                refusedBy.accept(no);
            }
        });
    }

    private boolean doorUsable(String id) {
        KnownDoor k = doors.get(id);
        return k != null && !k.state().equals("offline");
    }
}
