package io.concord.agents.medical;

import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Award;
import io.concord.agents.proto.WheelchairMessage.Done;
import io.concord.agents.proto.WheelchairMessage.Failed;
import io.concord.agents.proto.WheelchairMessage.Paused;
import io.concord.agents.proto.WheelchairMessage.Progress;
import io.concord.agents.proto.WheelchairMessage.Proposal;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.agents.proto.WheelchairMessage.Rejection;
import io.concord.agents.proto.WheelchairMessage.Resumed;
import io.concord.agents.proto.WheelchairMessage.TransportCall;
import io.concord.agents.proto.WheelchairMessage.TransportRequest;
import io.concord.layers.authority.Operators;
import io.concord.layers.authority.Policy;
import io.concord.layers.authority.SignedOrder;
import io.concord.agents.proto.WheelchairMessage.Withdrawal;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.WakerBehaviour;
import io.concord.core.proto.ContractNetInitiator;
import io.concord.core.proto.FipaProtocols;
import io.concord.layers.Platform;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * The Medical agent: takes patient transports (from code, {@link #transport}, or by ACL REQUEST
 * {@code transport-request}), and gives each to a chair by FIPA Contract Net:
 * a CFP to every chair in the yellow pages with a deadline, the best proposal by the utility
 * U = 100 (3 + TP) / (3 Cost + TP (Path + Unload)), ACCEPT-PROPOSAL to it and REJECT-PROPOSAL to
 * the others. Several auctions run at once, each with its own deadline. A task whose chair fails,
 * or sends no result by the time its proposal's cost allows (three times it, and two minutes), is
 * auctioned again, up to three times.
 *
 * <p>A chair that cannot drive now (offline, its e-stop pressed, paused) refuses with
 * {@code unavailable true}; when no chair proposes and one of them said so, the task is not
 * dropped: it is auctioned again every {@link Settings#retryMs()} until a chair takes it, and
 * fails with "no chair can do it" only after {@link Settings#waitForChairMs()}. A chair that
 * pauses a task it holds (INFORM {@code paused}) gets {@link Settings#pausedMs()} more for its
 * result, renewed with each notice it sends; a chair at work reports its progress (INFORM
 * {@code progress}: each phase, each node, every 20 s) and gets {@link Settings#progressMs()} more
 * from each report. Once the chair has the patient on board the task is never withdrawn nor
 * auctioned again: the patient is no longer at the pick-up.
 */
public class MedicalAgent extends Agent {
    /** The priorities of the dissertation: routine, urgent, emergency. */
    public static final double[] PRIORITIES = {0, 1.5, 3};

    /**
     * How a transport ended.
     *
     * @param task     its id
     * @param done     true if a chair reported it done
     * @param chair    the chair that did it or failed it last, or null
     * @param reason   why it failed, or null
     * @param auctions how many auctions it took
     */
    public record Outcome(String task, boolean done, String chair, String reason, int auctions) {
    }

    /**
     * Settings.
     *
     * @param auctionMs      how long chairs have to propose
     * @param maxAuctions    how many auctions a task gets when its chairs fail it or go silent
     * @param waitForChairMs how long a task waits for a chair while every chair is unavailable
     * @param retryMs        how often it asks again meanwhile
     * @param pausedMs       how much longer a chair that paused a task gets, from each notice
     * @param progressMs     how much longer a chair at work on a task gets, from each progress report
     *                       (0: its quote alone sets the deadline)
     * @param dwellKnown     whether an alarm for a chair in loading or unloading no longer than the
     *                       task asked is taken as the planned wait it is (false only in tests)
     */
    public record Settings(long auctionMs, int maxAuctions, long waitForChairMs, long retryMs, long pausedMs, long progressMs,
                           boolean dwellKnown) {
        /**
         * Two seconds to propose, three auctions, two minutes' wait for a chair asked every 5 s, 2
         * minutes from each pause notice and from each progress report.
         */
        public static Settings standard() {
            return new Settings(2_000, 3, 120_000, 5_000, 120_000, 120_000);
        }

        /**
         * The same with {@code dwellKnown} true: a fleet monitor's alarm for a chair in loading or
         * unloading no longer than the task asked is logged as no alarm (tests switch it off).
         */
        public Settings(long auctionMs, int maxAuctions, long waitForChairMs, long retryMs, long pausedMs, long progressMs) {
            this(auctionMs, maxAuctions, waitForChairMs, retryMs, pausedMs, progressMs, true);
        }

        /** These settings with another {@code progressMs}. */
        public Settings withProgressMs(long ms) {
            return new Settings(auctionMs, maxAuctions, waitForChairMs, retryMs, pausedMs, ms, dwellKnown);
        }

        /** For tests: every alarm taken as one, a chair standing as asked for its patient included. */
        public Settings withoutDwellKnown() {
            return new Settings(auctionMs, maxAuctions, waitForChairMs, retryMs, pausedMs, progressMs, false);
        }
    }

    private final Settings settings;
    private final Consumer<String> log;
    private final Map<String, CompletableFuture<Outcome>> open = new LinkedHashMap<>();
    /** task -> the accepted proposal of its current auction. */
    private final Map<String, AclMessage> awarded = new LinkedHashMap<>();
    /** task -> the chair that won its last auction (kept a while: later proposals may still count it). */
    private final Map<String, String> winners = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, String> eldest) {
            return size() > 1_000;
        }
    };
    private long next;
    /** task -> its contract net now. */
    private final Map<String, ContractNetInitiator> running = new LinkedHashMap<>();
    /**
     * An alarm of the fleet monitor (the traffic agent): {@code chair} has made no progress for
     * {@code seconds}; {@code task}, the transport it holds for this agent (or null); urgent when that
     * transport's patient is on board.
     */
    public record Alarm(long atMs, String chair, long seconds, String waits, String task, boolean urgent) {
    }

    private final List<Alarm> alarms = new ArrayList<>();
    /** task -> why the chair that held it last failed it (kept for the reason of a later round nobody proposes for). */
    private final Map<String, String> lastFailure = new LinkedHashMap<>();

    /** The fleet monitor's alarms heard so far, in order. */
    public List<Alarm> alarms() {
        return List.copyOf(alarms);
    }

    /** task -> the last progress report of the chair it was given to. */
    private final Map<String, Progress> progress = new LinkedHashMap<>();
    /** What this agent keeps of an open task's phases, to tell a planned dwell from a stall. */
    private static final class Phases {
        /** How long its patient takes to get on, and to get off (seconds, as asked). */
        final double dwellS;
        /** Since when (this agent's clock) its chair has been in the phase it last reported; null before the first. */
        Long since;
        /** When its chair last left loading or unloading (its patient on, or off); null before. */
        Long dwellEnded;
        /** The dwells (by the time they are counted from) whose end is watched ({@link #recheckAfterDwell}). */
        final Set<Long> rechecks = new HashSet<>();

        Phases(double dwellS) {
            this.dwellS = dwellS;
        }
    }

    /** task -> its phases, while it is open. */
    private final Map<String, Phases> phases = new LinkedHashMap<>();
    /** Tasks whose chair went silent with the patient on board: its result is still awaited, from that chair alone. */
    private final Map<String, Consumer<AclMessage>> awaitedAboard = new LinkedHashMap<>();
    /** task -> who asked for it (an agent's full name): a member cancels only its own. */
    private final Map<String, String> askers = new LinkedHashMap<>();
    /** The operators whose signed cancel withdraws any transport (the ward's, as its control agents trust them). */
    private volatile Operators operators = Operators.none();
    /** task -> auctions held (conversation ids stay unique while a task waits for a chair). */
    private final Map<String, Integer> auctionsHeld = new LinkedHashMap<>();

    /** A Medical agent with the standard settings. */
    public MedicalAgent(Consumer<String> log) {
        this(Settings.standard(), log);
    }

    public MedicalAgent(Settings settings, Consumer<String> log) {
        this.settings = settings;
        // Every line about a transport goes into its story too (the audit trail).
        this.log = line -> {
            log.accept(line);
            audit.logged(line, currentTimeMillis());
        };
    }

    private final TransportAudit audit = new TransportAudit();

    /** The audit trail of the transports this agent was asked for. Thread-safe. */
    public TransportAudit audit() {
        return audit;
    }

    /** What an audit answer holds at most, in characters (it travels in one datagram). */
    static final int AUDIT_CHARS = 40_000;

    /** The utility of a proposal (the dissertation's equation 6.1). */
    public static double utility(double cost, double path, double unload, double priority) {
        return 100 * (3 + priority) / (3 * cost + priority * (path + unload));
    }

    @Override
    protected void setup() {
        Platform.of(this).register(ServiceDescription.of(Services.MEDICAL, getLocalName()));
        Inbox.each(this, MessageTemplate.matchOntology(Services.ONTOLOGY).and(WheelchairMessage.matching(Paused.class)
                .or(WheelchairMessage.matching(Resumed.class)).or(WheelchairMessage.matching(Progress.class))), this::statusNotice);
        Inbox.each(this, MessageTemplate.matchOntology(Services.ONTOLOGY).and(WheelchairMessage.matching(WheelchairMessage.Stalled.class)),
                this::stalled);
        // The result of a task whose chair went silent with the patient on board (its contract ended).
        Inbox.each(this, WheelchairMessage.matching(Done.class).or(WheelchairMessage.matching(Failed.class))
                .and(m -> WheelchairMessage.tryDecode(m).map(w -> awaitedAboard.containsKey(taskOf(w))).orElse(false)),
                m -> {
                    WheelchairMessage w = WheelchairMessage.decode(m);
                    AclMessage winner = awarded.get(taskOf(w));
                    if (winner != null && winner.getSender().equals(m.getSender())) {
                        resultAfterSilence(m, w);
                    }
                });
        // The audit trail, for the front desk and any member of the platform: QUERY-REF "audit" (the
        // latest transports) or "audit T3" (one, with its story), answered with JSON.
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.QUERY_REF)
                .and(m -> m.getOntology() == null || Services.ONTOLOGY.equals(m.getOntology()))
                .and(m -> m.getContent() != null && m.getContent().trim().matches("audit( T\\d{1,9})?")), m -> send(m.createReply()
                .setPerformative(Performative.INFORM).setLanguage("application/json").setContent(AuditJson.answer(audit, m.getContent().trim()))));
        MessageTemplate requests = MessageTemplate.matchPerformative(Performative.REQUEST).and(WheelchairMessage.matching(TransportRequest.class));
        Inbox.each(this, requests, m -> {
            try {
                Policy.Decision may = Policy.defaults().decide(Policy.principalOf(m, getAID().platform()), Policy.Service.TRANSPORT_REQUEST);
                if (!may.allowed()) {
                    log.accept(getLocalName() + ": refuses a transport asked by " + m.getSender().name() + ": " + may.reason());
                    send(m.createReply().setPerformative(Performative.REFUSE).setContent(Refused.because(may.reason()).encode()));
                    return;
                }
                TransportRequest r = WheelchairMessage.decode(m, TransportRequest.class);
                // The AGREE is the request's own text.
                send(m.createReply().setPerformative(Performative.AGREE).setContent(m.getContent()));
                transportOnLoop(r.from(), r.to(), r.priority(), r.unload(), m.getSender().name(), m.getConversationId()).thenAccept(o -> send(m.createReply()
                        .setPerformative(o.done() ? Performative.INFORM : Performative.FAILURE).setContent(answer(o))));
            } catch (IllegalArgumentException e) {
                send(m.createReply().setPerformative(Performative.REFUSE).setContent(Refused.because(e.getMessage()).encode()));
            }
        });
        MessageTemplate cancels = MessageTemplate.matchPerformative(Performative.REQUEST)
                .and(WheelchairMessage.matching(WheelchairMessage.CancelRequest.class));
        Inbox.each(this, cancels, this::cancelRequested);
        // Any other REQUEST is answered, saying what is wrong or what this agent takes.
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.REQUEST).and(MessageTemplate.not(requests.or(cancels))),
                m -> WheelchairMessage.notTaken(m, "the Medical agent takes transport-request and cancel-request", this::send));
    }

    /** How a transport asked for by REQUEST ended, for whoever asked. */
    private static String answer(Outcome o) {
        String chair = o.chair(); // left out when no chair took it
        String reason = o.reason() == null ? "" : o.reason();
        return o.done() ? new Done(o.task(), null, chair, reason).encode() : new Failed(o.task(), chair, reason).encode();
    }

    /**
     * Asks for a patient to be taken from one node to another. Thread-safe: from another thread
     * the auction starts on the agent's loop.
     *
     * @param priority TP: 0, 1.5 or 3
     * @param unloadS  seconds to load and to unload the patient
     */
    public CompletableFuture<Outcome> transport(int from, int to, double priority, double unloadS) {
        if (runtime().inLoop()) {
            return transportOnLoop(from, to, priority, unloadS, getAID().name(), null);
        }
        CompletableFuture<Outcome> f = new CompletableFuture<>();
        runtime().execute(() -> transportOnLoop(from, to, priority, unloadS, getAID().name(), null).whenComplete((o, e) -> {
            if (e != null) {
                f.completeExceptionally(e);
            } else {
                f.complete(o);
            }
        }));
        return f;
    }

    private CompletableFuture<Outcome> transportOnLoop(int from, int to, double priority, double unloadS, String askedBy, String conversation) {
        if (priority < 0) {
            throw new IllegalArgumentException("priority must be 0 or more (0, 1.5 or 3), got " + priority);
        }
        String id = "T" + (++next);
        CompletableFuture<Outcome> f = new CompletableFuture<>();
        open.put(id, f);
        audit.asked(id, askedBy, conversation, currentTimeMillis(), from, to, priority);
        askers.put(id, askedBy);
        phases.put(id, new Phases(unloadS));
        f.whenComplete((o, e) -> {
            if (o != null) {
                audit.ended(id, o.done(), o.chair(), o.reason(), currentTimeMillis());
            }
            open.remove(id);
            awarded.remove(id);
            running.remove(id);
            progress.remove(id);
            phases.remove(id);
            awaitedAboard.remove(id);
            auctionsHeld.remove(id);
            lastFailure.remove(id);
            askers.remove(id);
        });
        log.accept(String.format(Locale.ROOT, "%s: transport %s from node %d to node %d, priority %.1f, unload %.0f s",
                getLocalName(), id, from, to, priority, unloadS));
        auction(id, from, to, priority, unloadS, 1, f, -1);
        return f;
    }

    /** A chair's word on a task it holds: paused (it gets longer for its result) or resumed. */
    private void statusNotice(AclMessage m) {
        try {
            WheelchairMessage.decode(m).to(new WheelchairMessage.Handler() {
                @Override
                public void onPaused(Paused p, AclMessage m) {
                    statusNotice(m, p.task(), " paused on ", p.reason());
                }

                @Override
                public void onResumed(Resumed r, AclMessage m) {
                    statusNotice(m, r.task(), " resumed on ", r.reason());
                }

                @Override
                public void onProgress(Progress p, AclMessage m) {
                    progressReport(m, p);
                }
            }, m);
        } catch (IllegalArgumentException e) {
            log.accept(getLocalName() + ": ignores a malformed notice from " + m.getSender().name() + ": " + e.getMessage());
        }
    }

    private void statusNotice(AclMessage m, String task, String what, String reason) {
        AclMessage winner = awarded.get(task);
        if (winner == null || !winner.getSender().equals(m.getSender())) {
            return; // not a task of this agent's, or not that chair's any more
        }
        ContractNetInitiator cn = running.get(task);
        if (cn != null) {
            cn.postponeResultDeadline(settings.pausedMs());
        }
        log.accept(getLocalName() + ": " + task + what + m.getSender().localName() + ": " + reason);
    }

    /**
     * A chair at work on a task it holds: it gets {@link Settings#progressMs()} more for its result
     * from each report, however long it is held up, and so do the tasks queued behind it on that
     * chair; once it has the patient on board, the task is never withdrawn from it nor auctioned again.
     */
    private void progressReport(AclMessage m, Progress p) {
        AclMessage winner = awarded.get(p.task());
        if (winner == null || !winner.getSender().equals(m.getSender())) {
            return; // not a task of this agent's, or not that chair's any more
        }
        Progress before = progress.put(p.task(), p);
        audit.phase(p.task(), m.getSender().localName(), p.phase(), currentTimeMillis());
        if (settings.progressMs() > 0) {
            // The chair's other tasks wait in its queue behind this one: they get the same time (a
            // queue of three behind a chair held up is not three silent tasks; 20 chairs, 50 tasks).
            awarded.forEach((task, w) -> {
                ContractNetInitiator cn = running.get(task);
                if (cn != null && w.getSender().equals(m.getSender())) {
                    cn.postponeResultDeadline(settings.progressMs());
                }
            });
        }
        if (before == null || !before.phase().equals(p.phase())) {
            Phases ph = phases.get(p.task());
            if (ph != null) {
                ph.since = currentTimeMillis();
                if (before != null && Progress.DWELLS.contains(before.phase())) {
                    ph.dwellEnded = currentTimeMillis();
                }
            }
            log.accept(getLocalName() + ": " + p.task() + " on " + m.getSender().localName() + ": " + p.phase() + " at node " + p.node()
                    + (p.patientOnBoard() ? " (the patient is on board)" : ""));
        } else if (before.node() != p.node() || !java.util.Objects.equals(before.waits(), p.waits())) {
            // The way it goes, node by node, and what it waits for (its route, a door): the story
            // has it; the log keeps to the phases.
            audit.logged(getLocalName() + ": " + p.task() + " on " + m.getSender().localName() + ": " + p.phase() + " at node " + p.node()
                    + (p.waits() == null ? "" : ", waiting for " + p.waits()), currentTimeMillis());
        }
        if (awaitedAboard.containsKey(p.task())) {
            log.accept(getLocalName() + ": " + m.getSender().localName() + " is heard again with " + p.task() + "'s patient at node " + p.node());
        }
    }

    /** The fleet monitor's alarm: logged, urgent if the chair has one of this agent's patients on board. */
    private void stalled(AclMessage m) {
        WheelchairMessage.Stalled st;
        try {
            st = WheelchairMessage.decode(m, WheelchairMessage.Stalled.class);
        } catch (IllegalArgumentException e) {
            log.accept(getLocalName() + ": ignores a malformed alarm from " + m.getSender().name() + ": " + e.getMessage());
            return;
        }
        String task = null;
        boolean urgent = false;
        for (Map.Entry<String, AclMessage> e : awarded.entrySet()) {
            if (e.getValue().getSender().name().equals(st.chair()) && open.containsKey(e.getKey())) {
                boolean aboard = patientOnBoard(e.getKey());
                if (task == null || aboard) {
                    task = e.getKey();
                    urgent = aboard;
                }
            }
        }
        String chair = st.chair().contains("@") ? st.chair().substring(0, st.chair().indexOf('@')) : st.chair();
        String dwell = task == null || !settings.dwellKnown() ? null : plannedDwell(task);
        if (dwell != null) {
            // Standing as asked while the patient gets on or off is no stall; the monitor raises
            // its alarm again later (at twice the limit, ...), and one past the plan is heard then.
            log.accept(getLocalName() + ": " + chair + " (" + task + ") has made no progress for " + st.seconds() + " s: " + dwell
                    + ", not an alarm");
            Phases ph = phases.get(task);
            recheckAfterDwell(task, chair, st.seconds() * 1000, ph.since + (long) (ph.dwellS * 1000), ph.since, st.waits());
            return;
        }
        Long ended = task == null || !settings.dwellKnown() || !phases.containsKey(task) ? null : phases.get(task).dwellEnded;
        long quietSince = currentTimeMillis() - st.seconds() * 1000;
        if (ended != null && quietSince < ended && currentTimeMillis() - ended < st.seconds() * 1000 && progress.get(task) != null) {
            // The monitor counts from the chair's arrival (it has not driven on since): most of this
            // wait was the patient getting on or off.
            log.accept(getLocalName() + ": " + chair + " (" + task + ") has made no progress for " + st.seconds() + " s: its patient"
                    + " was " + (patientOnBoard(task) ? "on board" : "off") + " " + (currentTimeMillis() - ended) / 1000
                    + " s ago, as asked; not an alarm yet");
            recheckAfterDwell(task, chair, st.seconds() * 1000, ended, ended, st.waits());
            return;
        }
        raise(task, chair, st.seconds(), st.waits(), urgent, "has made no progress for " + st.seconds() + " s; it waits for " + st.waits(),
                "no progress for " + st.seconds() + " s, waiting for " + st.waits());
    }

    /**
     * An alarm: kept ({@link #alarms()}), in the log ({@code what} the chair has done, urgent if its
     * patient is on board), and in the task's audit trail ({@code audited}) if it is one of this agent's.
     */
    private void raise(String task, String chair, long seconds, String waits, boolean urgent, String what, String audited) {
        alarms.add(new Alarm(currentTimeMillis(), chair, seconds, waits, task, urgent));
        log.accept(getLocalName() + ": " + (urgent ? "URGENT ALARM: " + task + "'s patient is on board " + chair + ", which"
                : "ALARM: " + chair + (task == null ? "" : " (" + task + ")")) + " " + what);
        if (task != null) {
            audit.logged(getLocalName() + ": " + (urgent ? "urgent " : "") + "alarm for " + chair + ": " + audited, currentTimeMillis());
        }
    }

    /**
     * After an alarm taken for a planned dwell (or one that came just after it, counted from the
     * chair's arrival): once the dwell is over ({@code dwellEnd}) and the monitor's limit has passed
     * again, a chair that has reported no other node since is an alarm of this agent's own (the
     * monitor's next one may be long after, its alarms doubling from the chair's arrival). Once per
     * dwell ({@code key}); the alarm says what the monitor said the chair waited for ({@code lastWaits}).
     */
    private void recheckAfterDwell(String task, String chair, long limitMs, long dwellEnd, long key, String lastWaits) {
        Progress at = progress.get(task);
        Phases ph = phases.get(task);
        if (at == null || ph == null || !ph.rechecks.add(key)) {
            return;
        }
        addBehaviour(new WakerBehaviour(this, Math.max(0, dwellEnd + limitMs - currentTimeMillis())) {
            @Override
            protected void onWake() {
                ph.rechecks.remove(key);
                Progress now = progress.get(task);
                if (now == null || !open.containsKey(task) || now.node() != at.node() || !now.chair().equals(at.chair())) {
                    return; // ended, or it drove on
                }
                boolean urgent = patientOnBoard(task);
                long past = (currentTimeMillis() - dwellEnd) / 1000;
                String waits = lastWaits + "; it has stood at node " + at.node() + " " + past + " s past the time asked for its patient";
                raise(task, chair, past, waits, urgent, "has stood at node " + at.node() + " " + past + " s past the time asked for its patient",
                        past + " s past the time asked at node " + at.node());
            }
        });
    }

    /**
     * If the chair given this task has been in loading or unloading no longer than the task's
     * time for it ({@code unload}): in words ("the patient gets off at node 12, 120 s of the 400 s
     * asked"); else null.
     */
    private String plannedDwell(String task) {
        Progress p = progress.get(task);
        Phases ph = phases.get(task);
        if (p == null || ph == null || ph.since == null || !Progress.DWELLS.contains(p.phase())) {
            return null;
        }
        double s = ph.dwellS;
        long stood = (currentTimeMillis() - ph.since) / 1000;
        if (stood > s) {
            return null;
        }
        return String.format(Locale.ROOT, "the patient gets %s at node %d, %d s of the %.0f s asked",
                p.phase().equals("loading") ? "on" : "off", p.node(), stood, s);
    }

    /** True if the chair given this task has said it has the patient on board. */
    private boolean patientOnBoard(String task) {
        Progress p = progress.get(task);
        return p != null && p.patientOnBoard();
    }

    private static String taskOf(WheelchairMessage w) {
        return w instanceof Done d ? d.task() : w instanceof Failed f ? f.task() : null;
    }

    /** The result, at last, of a task whose chair went silent with the patient on board. */
    private void resultAfterSilence(AclMessage m, WheelchairMessage w) {
        log.accept(getLocalName() + ": " + m.getSender().localName() + (w instanceof Done ? " reports " : " failed ") + taskOf(w)
                + " after its silence" + (w instanceof Failed f ? ": " + f.reason() : ""));
        awaitedAboard.remove(taskOf(w)).accept(m);
    }

    /**
     * Withdraws a transport (the staff changed their mind): the chair it was given to gets a
     * CANCEL and stops driving it; the transport ends, not done, with the reason. False if it has
     * ended already, or if its patient is on board (then the chair drives on to the drop-off).
     * Thread-safe.
     */
    public CompletableFuture<Boolean> cancel(String task, String why) {
        return withdrawal(task, why).thenApply(refused -> refused == null);
    }

    /**
     * As {@link #cancel}, saying why not: completes with null once the transport is withdrawn, or
     * with the reason it is not (it has ended or is unknown; its patient is on board). Thread-safe.
     */
    public CompletableFuture<String> withdrawal(String task, String why) {
        CompletableFuture<String> r = new CompletableFuture<>();
        Runnable run = () -> r.complete(cancelOnLoop(task, why));
        if (runtime().inLoop()) {
            run.run();
        } else {
            runtime().execute(run);
        }
        return r;
    }

    /** Withdraws {@code task}: null if done, else why not. Loop thread. */
    private String cancelOnLoop(String task, String why) {
        CompletableFuture<Outcome> f = open.get(task);
        if (f == null) {
            return "no transport " + task + " under way (it has ended, or there is none of that id)";
        }
        AclMessage winner = awarded.get(task);
        if (patientOnBoard(task)) {
            log.accept(getLocalName() + ": " + task + " is not withdrawn (" + why + "): its patient is on board "
                    + winner.getSender().localName() + ", which drives on to the drop-off");
            return task + "'s patient is on board " + winner.getSender().localName() + " (" + progress.get(task).phase()
                    + " at node " + progress.get(task).node() + "): it drives on to the drop-off; a transport with its patient on board is never withdrawn";
        }
        if (winner != null) {
            withdraw(task, winner);
        }
        log.accept(getLocalName() + ": " + task + " withdrawn: " + why);
        f.complete(new Outcome(task, false, winner == null ? null : winner.getSender().localName(), "withdrawn: " + why, 0));
        return null;
    }

    /**
     * The operators whose signed {@code cancel-request} withdraws any transport, not only the
     * sender's own (a console's operator cancelling the staff's transport). None by default.
     * Thread-safe.
     */
    public MedicalAgent operators(Operators ops) {
        this.operators = java.util.Objects.requireNonNull(ops, "operators").copy();
        return this;
    }

    /**
     * A REQUEST {@code cancel-request}: a member's only for a transport it asked for itself (the
     * policy's condition for a member); with an operator's signed order (a member carrying it), for
     * any transport. Answered AGREE with its own text once withdrawn, or REFUSE with why not.
     */
    private void cancelRequested(AclMessage m) {
        try {
            WheelchairMessage.CancelRequest c = WheelchairMessage.decode(m, WheelchairMessage.CancelRequest.class);
            Policy.Principal who = Policy.principalOf(m, getAID().platform());
            String operator = null;
            String badOrder = null;
            if (who == Policy.Principal.MEMBER && c.order() != null && !c.order().isBlank()) {
                try {
                    SignedOrder o = SignedOrder.parse(c.order());
                    badOrder = operators.verify(o, "cancel", c.task(), runtime().clock().epochMillis());
                    operator = badOrder == null ? o.operator() : null;
                } catch (IllegalArgumentException e) {
                    badOrder = e.getMessage();
                }
                who = operator != null ? Policy.Principal.OPERATOR : who;
            }
            Policy.Decision may = Policy.defaults().decide(who, Policy.Service.TRANSPORT_CANCEL);
            String reason = c.reason() == null || c.reason().isBlank() ? "no reason given" : c.reason();
            String refused = !may.allowed() ? may.reason()
                    : badOrder != null ? "the operator's order is refused: " + badOrder
                    : !open.containsKey(c.task()) ? "no transport " + c.task() + " under way (it has ended, or there is none of that id)"
                    : operator != null ? cancelOnLoop(c.task(), reason + " (by operator " + operator + ", asked by " + m.getSender().localName() + ")")
                    : !m.getSender().name().equals(askers.get(c.task()))
                    ? m.getSender().name() + " did not ask for " + c.task() + " ("
                            + (askers.containsKey(c.task()) ? askers.get(c.task()) : "the Medical agent's own staff") + " did): a member cancels only the transports "
                            + "it asked for, an operator any (a cancel-request with :order, signed with an operator key the ward configured)"
                    : cancelOnLoop(c.task(), reason + " (asked by " + m.getSender().localName() + ")");
            if (refused != null) {
                log.accept(getLocalName() + ": refuses to cancel " + c.task() + " for " + m.getSender().name() + ": " + refused);
                send(m.createReply().setPerformative(Performative.REFUSE).setContent(new Refused(c.task(), null, refused, false).encode()));
            } else {
                send(m.createReply().setPerformative(Performative.AGREE).setContent(m.getContent()));
            }
        } catch (IllegalArgumentException e) {
            send(m.createReply().setPerformative(Performative.REFUSE).setContent(Refused.because(e.getMessage()).encode()));
        }
    }

    /** Tells the chair whose proposal was accepted that the task is no longer its. */
    private void withdraw(String task, AclMessage winner) {
        AclMessage cancel = new AclMessage(Performative.CANCEL);
        cancel.addReceiver(winner.getSender());
        cancel.setProtocol(FipaProtocols.CONTRACT_NET);
        cancel.setOntology(Services.ONTOLOGY);
        cancel.setLanguage(Services.LANGUAGE);
        cancel.setConversationId(winner.getConversationId());
        cancel.setContent(new Withdrawal(task).encode());
        send(cancel);
    }

    /**
     * @param waitingSince when the task began to wait for a chair (every chair unavailable), on
     *                     the agent's clock in ms, or -1
     */
    private void auction(String id, int from, int to, double tp, double unload, int round, CompletableFuture<Outcome> f,
                         long waitingSince) {
        if (f.isDone()) {
            return;
        }
        int attempt = auctionsHeld.merge(id, 1, Integer::sum);
        audit.auction(id);
        List<AID> chairs = new ArrayList<>();
        for (AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.ofType(Services.TRANSPORT))) {
            chairs.add(e.aid());
        }
        if (chairs.isEmpty()) {
            f.complete(new Outcome(id, false, null, "no chair in the yellow pages", round));
            log.accept(getLocalName() + ": " + id + " cannot be done: no chair in the yellow pages");
            return;
        }
        AclMessage cfp = new AclMessage(Performative.CFP);
        chairs.forEach(cfp::addReceiver);
        cfp.setProtocol(FipaProtocols.CONTRACT_NET);
        cfp.setOntology(Services.ONTOLOGY);
        cfp.setLanguage(Services.LANGUAGE);
        cfp.setConversationId(id + "-" + attempt);
        cfp.setReplyByEpochMs(currentTimeMillis() + settings.auctionMs());
        cfp.setContent(new TransportCall(id, from, to, tp, unload).encode());
        log.accept(getLocalName() + ": CFP " + id + (attempt > 1 ? " (auction " + attempt + ")" : "") + " to " + chairs.size() + (chairs.size() == 1 ? " chair" : " chairs"));
        ContractNetInitiator cn = new ContractNetInitiator(this, cfp) {
            private AclMessage winner;
            private double winnerCost;

            @Override
            protected void handleAllResponses(List<AclMessage> responses, List<AclMessage> acceptances) {
                double best = -1;
                for (AclMessage r : responses) {
                    if (r.getPerformative() == Performative.PROPOSE) {
                        try {
                            Proposal p = WheelchairMessage.decode(r, Proposal.class);
                            double lost = lostElsewhere(p, r.getSender().localName());
                            double cost = p.cost() - lost;
                            double u = utility(cost, p.path(), p.unload(), tp);
                            // The chair's own log says the cost it bid; counted here without the
                            // tasks it bid for meanwhile that went to other chairs.
                            log.accept(String.format(Locale.ROOT, "%s: %s proposes cost %.1f%s, path %.1f for %s: U = %.3f",
                                    getLocalName(), r.getSender().localName(), cost,
                                    lost > 0 ? String.format(Locale.ROOT, " (%.1f bid, less %.1f for tasks since given to others)", p.cost(), lost) : "",
                                    p.path(), id, u));
                            if (u > best) {
                                best = u;
                                winner = r;
                                winnerCost = p.cost();
                            }
                        } catch (IllegalArgumentException e) {
                            log.accept(getLocalName() + ": ignores a malformed proposal from " + r.getSender().name() + ": " + e.getMessage());
                        }
                    } else if (r.getPerformative() == Performative.REFUSE) {
                        log.accept(getLocalName() + ": " + r.getSender().localName() + " refuses " + id + ": " + reasonOf(r));
                    }
                }
                for (AclMessage r : responses) {
                    if (r.getPerformative() != Performative.PROPOSE) {
                        continue;
                    }
                    AclMessage reply = r.createReply();
                    if (r == winner) {
                        reply.setPerformative(Performative.ACCEPT_PROPOSAL).setContent(new Award(id).encode());
                        awarded.put(id, r);
                        winners.put(id, r.getSender().localName());
                        audit.awarded(id, r.getSender().localName(), currentTimeMillis());
                        reply.setReplyByEpochMs(currentTimeMillis() + (long) (winnerCost * 3_000) + 120_000);
                        log.accept(getLocalName() + ": ACCEPT " + r.getSender().localName() + " for " + id);
                    } else {
                        reply.setPerformative(Performative.REJECT_PROPOSAL).setContent(new Rejection(id).encode());
                    }
                    acceptances.add(reply);
                }
                if (winner == null) {
                    boolean refused = responses.stream().anyMatch(r -> r.getPerformative() == Performative.REFUSE);
                    if (!refused && round < settings.maxAuctions()) {
                        // Nobody answered in time (a proposal late on a busy or lossy network, or a
                        // chair listed a moment ago): that is no answer yet, so the task is auctioned again.
                        log.accept(getLocalName() + ": no chair answered " + id + " in time; it is auctioned again");
                        auction(id, from, to, tp, unload, round + 1, f, waitingSince);
                        return;
                    }
                    List<String> unavailable = new ArrayList<>();
                    for (AclMessage r : responses) {
                        if (r.getPerformative() == Performative.REFUSE && unavailable(r)) {
                            unavailable.add(r.getSender().localName() + " " + reasonOf(r));
                        }
                    }
                    long now = currentTimeMillis();
                    long since = waitingSince < 0 ? now : waitingSince;
                    if (!unavailable.isEmpty()) {
                        if (now - since < settings.waitForChairMs()) {
                            log.accept(getLocalName() + ": no chair can take " + id + " now (" + String.join("; ", unavailable)
                                    + "); asks again in " + settings.retryMs() / 1000 + " s");
                            addBehaviour(new WakerBehaviour(myAgent, settings.retryMs()) {
                                @Override
                                protected void onWake() {
                                    auction(id, from, to, tp, unload, round, f, since);
                                }
                            });
                            return;
                        }
                        f.complete(new Outcome(id, false, null, "no chair can do it (waited " + settings.waitForChairMs() / 1000
                                + " s: " + String.join("; ", unavailable) + ")", round));
                        log.accept(getLocalName() + ": no chair can do " + id + " after " + settings.waitForChairMs() / 1000 + " s");
                        return;
                    }
                    // The real reason: what each chair said when it refused (no route, say), not just "nobody proposed".
                    List<String> refusals = new ArrayList<>();
                    for (AclMessage r : responses) {
                        if (r.getPerformative() == Performative.REFUSE) {
                            refusals.add(r.getSender().localName() + ": " + reasonOf(r));
                        }
                    }
                    String why = refusals.isEmpty() ? "no chair proposed" : "no chair proposed (" + String.join("; ", refusals) + ")";
                    if (lastFailure.containsKey(id)) {
                        why = lastFailure.get(id) + "; then " + why;
                    }
                    f.complete(new Outcome(id, false, null, why, round));
                    log.accept(getLocalName() + ": nobody can do " + id + (refusals.isEmpty() ? "" : ": " + String.join("; ", refusals)));
                }
            }

            @Override
            protected void handleInform(AclMessage inform) {
                log.accept(getLocalName() + ": " + inform.getSender().localName() + " reports " + id + " done");
                f.complete(new Outcome(id, true, inform.getSender().localName(), null, round));
            }

            @Override
            protected void handleFailure(AclMessage failure) {
                if (winner != null && failure.getSender().equals(winner.getSender())) {
                    String why = reasonOf(failure);
                    log.accept(getLocalName() + ": " + failure.getSender().localName() + " failed " + id + ": " + why);
                    if (patientOnBoard(id)) {
                        // The patient is not at the pick-up any more: nobody else is sent there.
                        f.complete(new Outcome(id, false, winner.getSender().localName(), aboard(why), round));
                        return;
                    }
                    again(failure.getSender().localName() + " failed: " + why);
                }
            }

            @Override
            protected void handleAllResultNotifications(List<AclMessage> results) {
                if (winner != null && !f.isDone() && results.stream().noneMatch(r -> r.getPerformative() == Performative.FAILURE)) {
                    String chair = winner.getSender().localName();
                    log.accept(getLocalName() + ": " + chair + " went silent on " + id);
                    if (patientOnBoard(id)) {
                        // Never withdrawn, never auctioned again: its result is awaited from that chair.
                        log.accept(getLocalName() + ": " + id + "'s patient is on board " + chair + " (last at node "
                                + progress.get(id).node() + "): nobody else is sent; an operator must find the chair");
                        awaitedAboard.put(id, r -> f.complete(r.getPerformative() == Performative.INFORM
                                ? new Outcome(id, true, chair, null, round) : new Outcome(id, false, chair, aboard(reasonOf(r)), round)));
                        return;
                    }
                    // Withdrawn from that chair, in case it still drives it: nobody carries the patient twice.
                    withdraw(id, winner);
                    again(chair + " went silent");
                }
            }

            private String aboard(String why) {
                Progress p = progress.get(id);
                return winner.getSender().localName() + " failed with the patient on board at node " + p.node() + ": " + why
                        + "; nobody else was sent (the patient is not at node " + from + ")";
            }

            private void again(String why) {
                if (f.isDone()) {
                    return;
                }
                lastFailure.put(id, why);
                if (round >= settings.maxAuctions()) {
                    f.complete(new Outcome(id, false, winner.getSender().localName(), why, round));
                } else {
                    auction(id, from, to, tp, unload, round + 1, f, -1);
                }
            }
        };
        running.put(id, cn);
        addBehaviour(cn);
    }

    /** A refusal from a chair that cannot drive now and may later (offline, e-stop, paused). */
    private static boolean unavailable(AclMessage refuse) {
        return WheelchairMessage.tryDecode(refuse).map(w -> w instanceof Refused r && r.unavailable()).orElse(false);
    }

    /**
     * Seconds of a proposal's cost that count other proposals of that chair which another chair
     * has won since (auctions run at once, and each chair counts all its open proposals).
     */
    private double lostElsewhere(Proposal proposal, String chair) {
        double s = 0;
        for (Proposal.Pending p : proposal.pending()) {
            String winner = winners.get(p.task());
            if (winner != null && !winner.equals(chair)) {
                s += p.seconds();
            }
        }
        return s;
    }

    private static String reasonOf(AclMessage m) {
        String r = WheelchairMessage.reasonOf(m);
        return r == null ? String.valueOf(m.getContent()) : r;
    }
}
