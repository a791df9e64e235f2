package io.concord.agents.door;

import io.concord.agents.map.Door;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.DoorOpen;
import io.concord.agents.proto.WheelchairMessage.DoorState;
import io.concord.agents.proto.WheelchairMessage.Failure;
import io.concord.agents.proto.WheelchairMessage.OpenQueued;
import io.concord.agents.proto.WheelchairMessage.OpenRequest;
import io.concord.agents.proto.WheelchairMessage.PassConfirmed;
import io.concord.agents.proto.WheelchairMessage.PassRequest;
import io.concord.agents.proto.WheelchairMessage.Passed;
import io.concord.agents.proto.WheelchairMessage.Here;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.agents.proto.WheelchairMessage.StateQuery;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.TickerBehaviour;
import io.concord.core.proto.RefuseException;
import io.concord.core.proto.SubscriptionResponder;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * A door agent, one per door of the map, on the door's mechanism ({@link DoorDriver}). It runs
 * the dissertation's state machine (closed -> opening -> open -> closing -> closed), stops when
 * the leaf meets something and opens again, closes after a timeout with nobody in the doorway,
 * and reports OFFLINE while its mechanism has failed. It opens only for chairs it confirmed
 * (a planner asked it to let the chair pass), keeps a session per chair that lapses when the
 * chair goes silent, and lets one chair through the doorway at a time.
 *
 * <p>Conversations (content: {@link WheelchairMessage}):
 * <ul>
 *   <li>REQUEST {@code pass-request} from a planner: CONFIRM, or REFUSE while offline.</li>
 *   <li>REQUEST {@code open-request} from a chair: AGREE {@code open-queued}, then INFORM {@code door-open} when the door is open and
 *       the doorway is the chair's; REFUSE if the chair was not confirmed; FAILURE if offline.</li>
 *   <li>INFORM {@code passed} from the chair in the doorway: the next one's turn.</li>
 *   <li>SUBSCRIBE {@code state-query}: AGREE with the door's {@code door-state}, then INFORM {@code door-state} on every change.</li>
 * </ul>
 */
public class DoorAgent extends Agent {
    /** The door's states, the dissertation's and OFFLINE. */
    public enum State { CLOSED, OPENING, OPEN, CLOSING, OFFLINE }

    /** Timings of a door agent. */
    public record Settings(long closeAfterMs, long leaseMs, long passMs, long retryMs) {
        /** Closes 5 s after the doorway empties; a session lapses after 60 s of silence; a chair has 60 s to pass. */
        public static Settings standard() {
            return new Settings(5_000, 60_000, 60_000, 1_000);
        }
    }

    /** A chair waiting for its turn: its control agent, the chair's body as the doorway sees it, the request. */
    private record Waiting(String chair, String body, AclMessage request) {
    }

    private final DoorDriver door;
    private final Settings settings;
    private final Consumer<String> log;
    private State state = State.CLOSED;
    private final Map<String, Long> sessions = new LinkedHashMap<>();
    private final ArrayDeque<Waiting> queue = new ArrayDeque<>();
    private String passing;
    private long passingSinceMs;
    private long emptySinceMs = -1;
    private long blockedSinceMs = -1;
    private SubscriptionResponder subscriptions;

    /** A door agent with the standard timings, logging nothing. */
    public DoorAgent(DoorDriver door) {
        this(door, Settings.standard(), s -> { });
    }

    /** A door agent; {@code log} is told of every change of state and every grant. */
    public DoorAgent(DoorDriver door, Settings settings, Consumer<String> log) {
        this.door = door;
        this.settings = settings;
        this.log = log;
    }

    @Override
    protected void setup() {
        var spec = door.spec();
        state = door.mechanismFailed() ? State.OFFLINE : door.isOpen() ? State.OPEN : State.CLOSED;
        Platform.of(this).register(ServiceDescription.of(Services.DOOR, spec.id())
                .withProperty("kind", spec.kind().name().toLowerCase(Locale.ROOT))
                .withProperty("x", fmt(spec.centre().x())).withProperty("y", fmt(spec.centre().y())));
        subscriptions = new SubscriptionResponder(this, SubscriptionResponder.createMessageTemplate()) {
            @Override
            protected AclMessage handleSubscription(AclMessage subscribe) throws RefuseException {
                return subscribe.createReply().setPerformative(Performative.AGREE).setContent(stateContent().encode());
            }
        };
        addBehaviour(subscriptions);
        MessageTemplate mine = MessageTemplate.matchPerformative(Performative.REQUEST)
                .or(MessageTemplate.matchPerformative(Performative.INFORM));
        Inbox.each(this, mine, this::handle);
        addBehaviour(new TickerBehaviour(this, 100) {
            @Override
            protected void onTick() {
                tick();
            }
        });
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }

    /** The door's state now. */
    public State state() {
        return state;
    }

    /** The chairs that hold a session (confirmed, not lapsed), by AID name. */
    public List<String> sessions() {
        return new ArrayList<>(sessions.keySet());
    }

    /** The chair in the doorway, or null. */
    public String passing() {
        return passing;
    }

    /** Chairs waiting for their turn, by AID name. */
    public List<String> waiting() {
        return queue.stream().map(Waiting::chair).toList();
    }

    private DoorState stateContent() {
        return new DoorState(door.id(), state.name().toLowerCase(Locale.ROOT), door.openFraction(), door.spec().centre().x(),
                door.spec().centre().y());
    }

    private void handle(AclMessage m) {
        WheelchairMessage.dispatch(m, handler, this::send);
    }

    private final WheelchairMessage.Handler handler = new WheelchairMessage.Handler() {
        @Override
        public void onPassed(Passed p, AclMessage m) {
            String sender = m.getSender().name();
            if (sender.equals(passing)) {
                log.accept(door.id() + ": " + sender + " passed");
                passing = null;
                sessions.put(sender, currentTimeMillis());
            }
        }

        @Override
        public void onHere(Here h, AclMessage m) {
            String sender = m.getSender().name();
            if (sessions.containsKey(sender)) {
                sessions.put(sender, currentTimeMillis());
            }
        }

        @Override
        public void onPassRequest(PassRequest p, AclMessage m) {
            if (state == State.OFFLINE) {
                send(m.createReply().setPerformative(Performative.REFUSE).setContent(
                        new Refused(null, door.id(), "offline", false).encode()));
                return;
            }
            String chair = p.chair() != null ? p.chair() : m.getSender().name();
            sessions.put(chair, currentTimeMillis());
            log.accept(door.id() + ": confirms passage to " + chair);
            send(m.createReply().setPerformative(Performative.CONFIRM).setContent(new PassConfirmed(door.id(), chair).encode()));
        }

        @Override
        public void onOpenRequest(OpenRequest o, AclMessage m) {
            String sender = m.getSender().name();
            if (state == State.OFFLINE) {
                send(m.createReply().setPerformative(Performative.FAILURE).setContent(offline()));
            } else if (!sessions.containsKey(sender)) {
                send(m.createReply().setPerformative(Performative.REFUSE).setContent(new Refused(null, door.id(),
                        "not confirmed, or the session lapsed: a planner must ask this door to let the chair pass", false).encode()));
            } else {
                sessions.put(sender, currentTimeMillis());
                queue.removeIf(w -> w.chair().equals(sender));
                queue.add(new Waiting(sender, o.body(), m));
                send(m.createReply().setPerformative(Performative.AGREE).setContent(new OpenQueued(door.id(), queue.size()).encode()));
            }
        }

        @Override
        public void onStateQuery(StateQuery q, AclMessage m) {
            send(m.createReply().setPerformative(Performative.INFORM).setContent(stateContent().encode()));
        }

        @Override
        public void unknown(String verb, AclMessage m) {
            if (m.getPerformative() == Performative.REQUEST) {
                send(m.createReply().setPerformative(Performative.NOT_UNDERSTOOD)
                        .setContent("unknown request '" + verb + "'; a door takes pass-request, open-request, state-query (docs/wheelchair-protocol.md)"));
            }
        }
    };

    private String offline() {
        return new Failure(door.id(), null, "offline").encode();
    }

    private void tick() {
        long now = currentTimeMillis();
        State before = state;
        if (door.mechanismFailed()) {
            if (state != State.OFFLINE) {
                state = State.OFFLINE;
                for (Waiting w : queue) {
                    send(w.request().createReply().setPerformative(Performative.FAILURE).setContent(offline()));
                }
                queue.clear();
                passing = null;
            }
        } else if (state == State.OFFLINE) {
            state = door.isOpen() ? State.OPEN : door.isClosed() ? State.CLOSED : State.CLOSING;
            if (state == State.CLOSING) {
                door.close();
            }
        }
        if (state != State.OFFLINE) {
            // The door's motion and its closing are timed on the door's clock, sessions on the platform's.
            long doorMs = door.nowNs() / 1_000_000;
            motion(doorMs);
            leases(now);
            serve(now);
            closeWhenIdle(doorMs);
        }
        if (state != before) {
            log.accept(door.id() + ": " + before.name().toLowerCase(Locale.ROOT) + " -> " + state.name().toLowerCase(Locale.ROOT));
            AclMessage n = new AclMessage(Performative.INFORM).setContent(stateContent().encode());
            n.setOntology(Services.ONTOLOGY);
            n.setLanguage(Services.LANGUAGE);
            for (var s : new ArrayList<>(subscriptions.getSubscriptions())) {
                s.notify(n.copy());
            }
        }
    }

    private void motion(long now) {
        switch (state) {
            case OPENING -> {
                if (door.isOpen()) {
                    state = State.OPEN;
                    blockedSinceMs = -1;
                } else if (door.blocked()) {
                    // Stopped on something in the leaf's way: try again after a while.
                    if (blockedSinceMs < 0) {
                        blockedSinceMs = now;
                        log.accept(door.id() + ": stopped opening, " + door.lastContact() + " in the way");
                    } else if (now - blockedSinceMs >= settings.retryMs()) {
                        blockedSinceMs = -1;
                        door.open();
                    }
                } else if (door.motion() == DoorDriver.Motion.STILL) {
                    door.open();
                }
            }
            case CLOSING -> {
                if (door.isClosed()) {
                    state = State.CLOSED;
                } else if (door.blocked()) {
                    // The leaf met someone while closing: open again.
                    log.accept(door.id() + ": stopped closing on " + door.lastContact() + ", opens again");
                    door.open();
                    state = State.OPENING;
                }
            }
            default -> { }
        }
    }

    private void leases(long now) {
        List<String> lapsed = new ArrayList<>();
        for (Map.Entry<String, Long> e : sessions.entrySet()) {
            if (now - e.getValue() > settings.leaseMs() && !e.getKey().equals(passing)) {
                lapsed.add(e.getKey());
            }
        }
        for (String chair : lapsed) {
            sessions.remove(chair);
            queue.removeIf(w -> w.chair().equals(chair));
            log.accept(door.id() + ": the session of " + chair + " lapsed");
        }
        if (passing != null && now - passingSinceMs > settings.passMs()) {
            log.accept(door.id() + ": " + passing + " did not pass in time");
            sessions.remove(passing);
            passing = null;
        }
    }

    private void serve(long now) {
        if (queue.isEmpty()) {
            return;
        }
        if (state == State.CLOSED || state == State.CLOSING) {
            // A revolving leaf sweeps both sides: it does not start while anything stands in its way.
            if (door.spec().kind() == Door.Kind.ROTATING && door.sweepOccupied()) {
                return;
            }
            door.open();
            state = State.OPENING;
            return;
        }
        if (state != State.OPEN || passing != null) {
            return;
        }
        Waiting head = queue.peek();
        // One chair through the doorway at a time: the next waits until nobody else is in it.
        for (String who : door.inDoorway()) {
            if (!who.equals(head.body())) {
                return;
            }
        }
        queue.poll();
        passing = head.chair();
        passingSinceMs = now;
        log.accept(door.id() + ": open for " + passing);
        send(head.request().createReply().setPerformative(Performative.INFORM).setContent(new DoorOpen(door.id()).encode()));
    }

    private void closeWhenIdle(long now) {
        if (state != State.OPEN || passing != null || !queue.isEmpty()) {
            emptySinceMs = -1;
            return;
        }
        if (door.doorwayOccupied() || door.sweepOccupied()) {
            emptySinceMs = -1;
            return;
        }
        if (emptySinceMs < 0) {
            emptySinceMs = now;
        } else if (now - emptySinceMs >= settings.closeAfterMs()) {
            door.close();
            state = State.CLOSING;
            emptySinceMs = -1;
        }
    }
}
