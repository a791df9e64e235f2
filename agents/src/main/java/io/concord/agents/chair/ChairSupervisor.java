package io.concord.agents.chair;

import io.concord.core.time.Clock;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayDeque;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * The safety supervisor between the agents and any chair (docs/chair-safety.md): a
 * {@link ChairDriver} around another one that owns the arming state machine and decides what the
 * agents may command in each state. The agents command it as they would the chair; it passes
 * motion on only while {@link State#ARMED}, and sends neutral otherwise.
 *
 * <pre>
 *            resume()                 2 readings, board armed
 *   HELD ───────────────► ARMING ───────────────────────────► ARMED
 *    ▲  ▲                   │                                   │
 *    │  └───────────────────┴── e-stop, trip, reboot, refusal ──┘
 *    │                                                          │
 *    └─── link up ─── OFFLINE ◄────────── link down ────────────┘
 * </pre>
 *
 * <p>An e-stop, a watchdog trip, a board reboot, a refusal (NAK) or a link that went down moves it
 * to {@link State#HELD} with the cause ({@link #hold()}), logged once and counted
 * ({@link #counts()}), and told to the observer (the control agent, which pauses its task and
 * says why). Nothing the chair reports ends a hold: only {@link #resume} does, a decision of an
 * agent or an operator, and only while the link is up and the e-stop released. Resuming sends
 * neutral and waits until the board says it is armed in two readings (a chair without an arming
 * board, the simulated one, is armed at once); a refused resume says why. Every hold reaches the
 * chair as {@link ChairDriver#holdMotion()} (the driver forgets its last command), and the armed
 * state as {@link ChairDriver#releaseMotion()}.
 *
 * <p>A fault that recurs is not resumed by the agents for ever: the {@link Repeats}th lost link
 * (a cable, a board whose clock drifts out of its tolerance) within its window holds the chair for
 * an operator ({@link Hold#repeated()}), with the count in its reason. A watchdog trip or a frozen
 * host, the host being late on a busy machine, is resumed by the agents every time: slow is not dead.
 *
 * <p>Confined to the loop of the runtime that drives the chair, as every driver is. The
 * {@link Defence}s are there for tests: each hazard's test switches its defence off and watches
 * the hazard happen ({@link #withDefences}); production code uses {@link #ChairSupervisor(ChairDriver)}.
 */
public final class ChairSupervisor implements ChairDriver {
    private static final Logger LOG = LoggerFactory.getLogger(ChairSupervisor.class);

    /** Where the supervisor stands. */
    public enum State {
        /** The link to the chair is down. */
        OFFLINE,
        /** Motion is held: the agents' commands become neutral until {@link #resume}. */
        HELD,
        /** A resume was decided: neutral is sent until the board says it is armed. */
        ARMING,
        /** The agents' commands reach the motors. */
        ARMED
    }

    /** Why motion is held. */
    public enum Cause {
        /** Not armed since the driver started or the link came up. */
        START(0, true),
        /** The link to the chair went down (it may be up again; the board tripped meanwhile). */
        LINK(1, true),
        /** The board's watchdog stopped the motors: the host's commands came too late. */
        WATCHDOG(2, true),
        /** The host was frozen or starved: its driver did not send the command it held (it was older than the host's silence). */
        HOST_FROZEN(2, true),
        /** The board refused a command (a NAK) and said no more. */
        REFUSED(2, false),
        /** The e-stop was pressed (and may since have been released). */
        ESTOP(3, false),
        /** The board started again: its motors at zero, its counts and odometry from scratch. */
        REBOOT(4, false),
        /** An operator stopped it ({@link #holdByOperator}, the console's Stop all): only an operator's resume releases it. */
        OPERATOR(3, false);

        private final int rank;
        private final boolean agentMayResume;

        Cause(int rank, boolean agentMayResume) {
            this.rank = rank;
            this.agentMayResume = agentMayResume;
        }

        /**
         * True if the control agent may decide alone to resume after it (the chair was not stopped
         * by a person or by a reboot); false if a person must (an operator's resume).
         */
        public boolean agentMayResume() {
            return agentMayResume;
        }
    }

    /**
     * A hold: its cause and the chair's own words.
     *
     * @param cause    why
     * @param detail   what the chair said ("NAK not neutral for frame 812", "boot 8 after boot 7")
     * @param repeated null, or how often the cause recurred ("the 3rd link loss within 10 minutes"):
     *                 then only an operator resumes, whatever the cause
     */
    public record Hold(Cause cause, String detail, String repeated) {
        public Hold(Cause cause, String detail) {
            this(cause, detail, null);
        }

        /** True if the control agent may decide alone to resume: the cause allows it and it has not recurred too often. */
        public boolean agentMayResume() {
            return cause.agentMayResume() && repeated == null;
        }

        @Override
        public String toString() {
            return switch (cause) {
                case START -> "not armed yet";
                case LINK -> "the link to the chair went down";
                case WATCHDOG -> "the board's watchdog tripped";
                case HOST_FROZEN -> "the host was frozen";
                case REFUSED -> "the board refused a command";
                case ESTOP -> "the e-stop was pressed";
                case REBOOT -> "the board restarted";
                case OPERATOR -> "an operator stopped it";
            } + (detail == null || detail.isEmpty() ? "" : " (" + detail + ")")
                    + (repeated == null ? "" : "; " + repeated + ": an operator must resume it");
        }
    }

    /**
     * When a fault that the agents may resume after is one too many: the {@code count}th hold of
     * one cause within {@code windowMs} holds the chair for an operator.
     *
     * @param count    holds of one cause (1 or more)
     * @param windowMs within this many milliseconds (more than 0)
     */
    public record Repeats(int count, long windowMs) {
        /** 3 within 10 minutes. */
        public static final Repeats STANDARD = new Repeats(3, 600_000);

        public Repeats {
            if (count < 1 || windowMs <= 0) {
                throw new IllegalArgumentException("repeats need a count of 1 or more and a window over 0 ms, not " + count + " within "
                        + windowMs + " ms");
            }
        }
    }

    /** Told, on the loop, when motion is held and when it is armed again. */
    public interface Observer {
        /** Motion is held (or the hold's cause changed to a graver one). */
        void onHold(Hold hold);

        /** Motion is armed again, after the resume {@code decidedBy} asked for. */
        void onArmed(String decidedBy);
    }

    /** The supervisor's defences, each switched off only by a test that shows its hazard. */
    public enum Defence {
        /** An e-stop holds motion until a resume; off, the chair drives on when it is released. */
        ESTOP_HOLDS,
        /** A board that says it is not armed (a trip, a reboot, an e-stop unseen) holds motion; off, it is ignored. */
        ARMED_BIT_HOLDS,
        /** A refused command holds motion; off, the refused command is sent again and again. */
        REFUSAL_HOLDS,
        /** A board's reboot holds motion; off, it is ignored. */
        REBOOT_HOLDS,
        /** A link that went down holds motion when it comes back; off, driving goes on at once. */
        LINK_HOLDS,
        /** A fault that recurs ({@link Repeats}) holds the chair for an operator; off, the agents resume it for ever. */
        REPEATS_NEED_OPERATOR
    }

    private final ChairDriver chair;
    private final Set<Defence> defences;
    private final Clock clock;
    private final Repeats repeats;
    /** When each agent-resumable cause last held motion, within the repeats' window (ms of the clock). */
    private final Map<Cause, ArrayDeque<Long>> recent = new EnumMap<>(Cause.class);
    private final Map<String, Long> counts = new TreeMap<>();
    /** Why the link went down, as the driver said it just before; null once taken. */
    private String linkLoss;
    private ChairListener listener;
    private Observer observer;
    private State state;
    private Hold hold = new Hold(Cause.START, null);
    private boolean estopPressed;
    private boolean boardArmed;
    private int armedReadings;
    private String decidedBy;

    /** Who stopped the chair for an operator ({@link #holdByOperator}) since its last resume, or null. */
    private String operatorStop;

    /** Supervises {@code chair} with every defence on, on the system's clock, {@link Repeats#STANDARD}. */
    public ChairSupervisor(ChairDriver chair) {
        this(chair, Clock.system(), Repeats.STANDARD);
    }

    /** Supervises {@code chair} with every defence on, timing repeated faults on {@code clock}. */
    public ChairSupervisor(ChairDriver chair, Clock clock, Repeats repeats) {
        this(chair, EnumSet.allOf(Defence.class), clock, repeats);
    }

    private ChairSupervisor(ChairDriver chair, Set<Defence> defences, Clock clock, Repeats repeats) {
        this.chair = chair;
        this.clock = clock;
        this.repeats = repeats;
        this.defences = EnumSet.noneOf(Defence.class);
        this.defences.addAll(defences);
        this.state = chair.online() ? State.HELD : State.OFFLINE;
        this.boardArmed = !chair.reportsArming();
        chair.setListener(new ChairListener() {
            @Override
            public void onReadings(ChairReadings r) {
                readings(r);
            }

            @Override
            public void onOnline(boolean online) {
                online(online);
            }

            @Override
            public void onEvent(ChairEvent e) {
                event(e);
            }
        });
    }

    /**
     * A supervisor with only some defences: for the tests that show what each one stands against.
     * Never use it to drive a chair.
     */
    public static ChairSupervisor withDefences(ChairDriver chair, Set<Defence> defences) {
        return new ChairSupervisor(chair, defences, Clock.system(), Repeats.STANDARD);
    }

    /** As {@link #withDefences(ChairDriver, Set)}, on a test's clock and repeats. Never use it to drive a chair. */
    public static ChairSupervisor withDefences(ChairDriver chair, Set<Defence> defences, Clock clock, Repeats repeats) {
        return new ChairSupervisor(chair, defences, clock, repeats);
    }

    /** Sets the one observer of holds and resumes (replacing any before); null removes it. */
    public void setObserver(Observer o) {
        this.observer = o;
    }

    /** Where it stands. */
    public State state() {
        return state;
    }

    /** The current hold (while not {@link State#ARMED}; the last one otherwise). */
    public Hold hold() {
        return hold;
    }

    /** True while the agents' commands reach the motors. */
    public boolean armed() {
        return state == State.ARMED;
    }

    /** True while the chair's e-stop is pressed (as its last reading said). */
    public boolean estopPressed() {
        return estopPressed;
    }

    /** The chair it supervises. */
    public ChairDriver chair() {
        return chair;
    }

    /** What it has seen, counted: estop, watchdog, reboot, refused, link-down, hold, resume, ... */
    public Map<String, Long> counts() {
        return new TreeMap<>(counts);
    }

    /**
     * Why the chair cannot take a task now, or null if it can: offline, the e-stop pressed, or
     * held for a cause that needs a decision (a just-started or re-arming chair can).
     */
    public String whyNotAvailable() {
        if (state == State.OFFLINE || !chair.online()) {
            String why = chair.whyOffline();
            return "is offline (its link is down" + (why == null ? "" : ": " + why) + ")";
        }
        if (estopPressed && defences.contains(Defence.ESTOP_HOLDS)) {
            return "has its e-stop pressed";
        }
        if (state == State.HELD && !hold.agentMayResume()) {
            return "is paused: " + hold + "; it waits for an operator's resume";
        }
        if (state != State.ARMED && hold.cause() != Cause.START) {
            return "cannot drive yet: " + hold + "; it is re-arming";
        }
        return null;
    }

    /**
     * An operator's stop (the console's Stop all): motion is held as for an e-stop, and only an
     * operator's resume releases it; the agents never resume it by themselves, task or none, nor
     * after a link that drops and comes back meanwhile. A chair that is offline now is held so as
     * soon as its link is back.
     *
     * @param who who stopped it, for the log and the hold's words ("stop all by nurse Ada")
     */
    public void holdByOperator(String who) {
        count("operator-stop");
        operatorStop = who;
        if (state == State.OFFLINE) {
            hold = new Hold(hold.cause(), hold.detail(), "stopped by an operator (" + who + ")");
            LOG.warn("{}: offline; held for an operator once its link is back: {}", chair.name(), who);
            return;
        }
        holdFor(Cause.OPERATOR, who);
    }

    /** Who stopped the chair for an operator ({@link #holdByOperator}) since its last resume, or null. */
    public String operatorStop() {
        return operatorStop;
    }

    /**
     * Decides that motion may resume: neutral goes out, and the agents' commands reach the motors
     * once the board says it is armed. Null if it is resuming (or armed already), else why not.
     *
     * @param who who decided, for the log ("operator at the console", "control-chair1: the link is back")
     */
    public String resume(String who) {
        if (state == State.ARMED || state == State.ARMING) {
            return null;
        }
        if (state == State.OFFLINE || !chair.online()) {
            return chair.name() + " is offline";
        }
        if (estopPressed) {
            return chair.name() + "'s e-stop is still pressed: release it first";
        }
        count("resume");
        operatorStop = null;
        if (hold.repeated() != null) {
            recent.remove(hold.cause()); // an operator decided: the count of that fault starts again
        }
        decidedBy = who;
        if (hold.cause() == Cause.START) {
            LOG.info("{}: arms for the first time: decided by {}", chair.name(), who); // the normal start, not a fault
        } else {
            LOG.info("{}: resumes after {}: decided by {}", chair.name(), hold, who);
        }
        state = State.ARMING;
        armedReadings = 0;
        chair.stop();
        if (!chair.reportsArming()) {
            becomeArmed();
        } else if (!boardArmed) {
            chair.arm();   // the only way the board arms: this decision, never a heartbeat
        }
        return null;
    }

    // ---- ChairDriver ----------------------------------------------------------------------------

    @Override
    public String name() {
        return chair.name();
    }

    @Override
    public ChairLayout layout() {
        return chair.layout();
    }

    /** The powers reach the motors while armed; otherwise neutral goes out instead. */
    @Override
    public void drive(double leftPercent, double rightPercent) {
        if (state == State.ARMED) {
            chair.drive(leftPercent, rightPercent);
        } else {
            chair.stop();
        }
    }

    @Override
    public void stop() {
        chair.stop();
    }

    @Override
    public ChairReadings latest() {
        return chair.latest();
    }

    @Override
    public boolean online() {
        return chair.online();
    }

    @Override
    public boolean reportsArming() {
        return chair.reportsArming();
    }

    @Override
    public String whyOffline() {
        return chair.whyOffline();
    }

    @Override
    public Map<String, Long> linkDrops() {
        return chair.linkDrops();
    }

    @Override
    public void setListener(ChairListener l) {
        this.listener = l;
    }

    // ---- what the chair says --------------------------------------------------------------------

    private void readings(ChairReadings r) {
        if (r.emergencyStop() != estopPressed) {
            estopPressed = r.emergencyStop();
            if (estopPressed) {
                count("estop");
                if (defences.contains(Defence.ESTOP_HOLDS)) {
                    holdFor(Cause.ESTOP, null);
                }
            } else {
                LOG.info("{}: the e-stop is released; motion stays held until a resume", chair.name());
            }
        }
        if (r.faults().contains(ChairFault.WATCHDOG) && state == State.ARMED && defences.contains(Defence.ARMED_BIT_HOLDS)) {
            count("watchdog");
            holdFor(Cause.WATCHDOG, "the board reports its watchdog fault");
        }
        if (state == State.ARMING) {
            if (!boardArmed && !estopPressed) {
                chair.arm();   // again while it is not armed: an ARM lost on the wire, or one for a state since replaced
            }
            armedReadings = boardArmed && !estopPressed ? armedReadings + 1 : 0;
            // Two readings: the first may have left the board before it took the neutral command.
            if (armedReadings >= 2) {
                becomeArmed();
            }
        }
        if (state == State.ARMED && estopPressed && !defences.contains(Defence.ESTOP_HOLDS)) {
            chair.stop();
        }
        if (listener != null) {
            listener.onReadings(r);
        }
    }

    private void online(boolean up) {
        if (!up) {
            count("link-down");
            state = State.OFFLINE;
            chair.holdMotion();
            String repeated = repeated(Cause.LINK);
            hold = new Hold(Cause.LINK, linkLoss == null ? "no word from the chair" : linkLoss,
                    operatorStop != null ? "stopped by an operator before (" + operatorStop + ")" : repeated);
            linkLoss = null;
            LOG.warn("{}: holds motion: {}", chair.name(), hold);
            if (observer != null) {
                observer.onHold(hold);
            }
        } else {
            boardArmed = !chair.reportsArming();
            if (defences.contains(Defence.LINK_HOLDS) || hold.cause() != Cause.LINK) {
                state = State.HELD;
            } else {
                state = State.ARMED;
                chair.releaseMotion();
            }
        }
        if (listener != null) {
            listener.onOnline(up);
        }
    }

    private void event(ChairEvent e) {
        switch (e.kind()) {
            case REFUSED -> {
                count("refused");
                if (state == State.ARMED && defences.contains(Defence.REFUSAL_HOLDS)) {
                    holdFor(Cause.REFUSED, e.detail());
                }
            }
            case DISARMED -> {
                boardArmed = false;
                armedReadings = 0;
                if (defences.contains(Defence.ARMED_BIT_HOLDS) && state != State.OFFLINE) {
                    Cause c = switch (e.detail()) {
                        case "watchdog" -> Cause.WATCHDOG;
                        case "e-stop" -> Cause.ESTOP;
                        case "switch-on" -> Cause.REBOOT;
                        default -> Cause.LINK; // a new host session
                    };
                    // While arming, the board is not armed yet: that is expected, not a hold.
                    if (state == State.ARMED || state == State.HELD && hold.cause() == Cause.REFUSED && c.rank >= Cause.REFUSED.rank) {
                        // A refusal said nothing of why; the board's reason, when it comes, replaces it.
                        if (c == Cause.WATCHDOG) {
                            count("watchdog");
                        }
                        holdFor(c, "the board says it is not armed: " + e.detail());
                    }
                }
            }
            case ARMED -> boardArmed = true;
            case REBOOTED -> {
                count("reboot");
                boardArmed = false;
                if (defences.contains(Defence.REBOOT_HOLDS) && state != State.OFFLINE) {
                    holdFor(Cause.REBOOT, e.detail());
                }
            }
            case INCOMPATIBLE -> count("incompatible");
            case LINK_LOST -> linkLoss = e.detail();
            case HOST_FROZEN -> {
                count("host-frozen");
                if (state != State.OFFLINE) {
                    holdFor(Cause.HOST_FROZEN, e.detail());
                }
            }
            default -> { }
        }
        if (listener != null) {
            listener.onEvent(e);
        }
    }

    /** Holds motion for a cause; a held supervisor takes a graver cause only. */
    private void holdFor(Cause cause, String detail) {
        if (state == State.HELD && cause.rank < hold.cause().rank) {
            return;
        }
        boolean news = state != State.HELD || cause != hold.cause();
        state = State.HELD;
        chair.holdMotion();
        if (news) {
            hold = new Hold(cause, detail, repeated(cause));
            count("hold");
            LOG.warn("{}: holds motion: {}", chair.name(), hold);
            if (observer != null) {
                observer.onHold(hold);
            }
        }
    }

    /**
     * Notes one more hold of {@code cause}: null if the agents may still resume after it, else how
     * often it recurred within the window (then an operator must).
     */
    private String repeated(Cause cause) {
        // Only the link's faults recur towards an operator: a watchdog trip or a frozen host is the
        // host being late (a busy machine), which the agents resume every time (slow is not dead);
        // a link that keeps dropping (a cable, a board's clock out of its tolerance) is not.
        if (cause != Cause.LINK || !defences.contains(Defence.REPEATS_NEED_OPERATOR)) {
            return null;
        }
        long now = clock.nanoTime() / 1_000_000;
        ArrayDeque<Long> times = recent.computeIfAbsent(cause, c -> new ArrayDeque<>());
        times.addLast(now);
        while (now - times.peekFirst() > repeats.windowMs()) {
            times.removeFirst();
        }
        if (times.size() < repeats.count()) {
            return null;
        }
        count("repeated");
        String what = switch (cause) {
            case LINK -> "link loss";
            case WATCHDOG -> "watchdog trip";
            case HOST_FROZEN -> "host freeze";
            default -> cause.name().toLowerCase(java.util.Locale.ROOT);
        };
        String r = "the " + ordinal(times.size()) + " " + what + " within " + minutes(repeats.windowMs());
        LOG.warn("{}: {}: holds the chair for an operator (the agents no longer resume it by themselves)", chair.name(), r);
        return r;
    }

    private static String ordinal(int n) {
        int t = n % 100;
        String suffix = t >= 11 && t <= 13 ? "th" : switch (n % 10) {
            case 1 -> "st";
            case 2 -> "nd";
            case 3 -> "rd";
            default -> "th";
        };
        return n + suffix;
    }

    private static String minutes(long ms) {
        if (ms % 60_000 == 0) {
            long m = ms / 60_000;
            return m + (m == 1 ? " minute" : " minutes");
        }
        return ms / 1000.0 + " s";
    }

    private void becomeArmed() {
        state = State.ARMED;
        chair.releaseMotion();
        LOG.info("{}: armed again (decided by {})", chair.name(), decidedBy);
        if (observer != null) {
            observer.onArmed(decidedBy);
        }
    }

    private void count(String what) {
        counts.merge(what, 1L, Long::sum);
    }

    @Override
    public String toString() {
        return "ChairSupervisor[" + chair.name() + " " + state + (state == State.ARMED ? "" : ": " + hold) + "]";
    }
}
