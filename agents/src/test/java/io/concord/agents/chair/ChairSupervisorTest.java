package io.concord.agents.chair;

import io.concord.core.time.ManualClock;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The supervisor alone, on a fake chair whose board arms as docs/chair-protocol.md says: each
 * hazard with its defence on (the motors get neutral until a resume), and off (the hazard).
 */
class ChairSupervisorTest {

    /** A chair with an arming board, driven by hand: readings, events and the link as a test says. */
    static final class FakeChair implements ChairDriver {
        final List<String> commands = new ArrayList<>();
        ChairListener listener;
        boolean online = true;
        long seq;
        /** True between the supervisor's holdMotion() and releaseMotion(). */
        boolean motionHeld;
        int releases;

        @Override
        public String name() {
            return "chair1";
        }

        @Override
        public ChairLayout layout() {
            return ChairLayout.standard();
        }

        @Override
        public void drive(double l, double r) {
            commands.add(l == 0 && r == 0 ? "neutral" : "drive " + (int) l + "," + (int) r);
        }

        @Override
        public void holdMotion() {
            motionHeld = true;
            stop();
        }

        @Override
        public void releaseMotion() {
            motionHeld = false;
            releases++;
        }

        @Override
        public ChairReadings latest() {
            return null;
        }

        @Override
        public boolean online() {
            return online;
        }

        @Override
        public boolean reportsArming() {
            return true;
        }

        @Override
        public void setListener(ChairListener l) {
            listener = l;
        }

        void reading(boolean estop) {
            listener.onReadings(new ChairReadings(seq * 50_000_000, seq++, 0, 0, new double[layout().sensors().size()], false, 24,
                    estop, Set.of(), new Pose(0, 0, 0), null));
        }

        void event(ChairEvent.Kind k, String detail) {
            listener.onEvent(new ChairEvent(k, detail));
        }

        String last() {
            return commands.get(commands.size() - 1);
        }
    }

    /** Holds and resumes as the control agent hears them. */
    static final class Heard implements ChairSupervisor.Observer {
        final List<String> said = new ArrayList<>();

        @Override
        public void onHold(ChairSupervisor.Hold hold) {
            said.add("hold " + hold.cause());
        }

        @Override
        public void onArmed(String decidedBy) {
            said.add("armed by " + decidedBy);
        }
    }

    private static ChairSupervisor armedOn(FakeChair c, Set<ChairSupervisor.Defence> defences, Heard heard) {
        return armedOn(c, defences, heard, new ManualClock());
    }

    private static ChairSupervisor armedOn(FakeChair c, Set<ChairSupervisor.Defence> defences, Heard heard, ManualClock clock) {
        ChairSupervisor s = ChairSupervisor.withDefences(c, defences, clock, ChairSupervisor.Repeats.STANDARD);
        s.setObserver(heard);
        s.setListener(new ChairListener() {
            @Override
            public void onReadings(ChairReadings r) {
            }
        });
        assertEquals(ChairSupervisor.State.HELD, s.state(), "not armed at start");
        c.event(ChairEvent.Kind.DISARMED, "switch-on");
        assertNull(s.resume("the control agent at start"));
        assertEquals("neutral", c.last(), "resuming sends neutral");
        c.event(ChairEvent.Kind.ARMED, null);
        c.reading(false);
        s.drive(50, 50);
        assertEquals("neutral", c.last(), "one reading is not enough: it may have left the board before the neutral arrived");
        c.reading(false);
        s.drive(50, 50);
        assertEquals("drive 50,50", c.last());
        return s;
    }

    private static Set<ChairSupervisor.Defence> all() {
        return EnumSet.allOf(ChairSupervisor.Defence.class);
    }

    private static Set<ChairSupervisor.Defence> allBut(ChairSupervisor.Defence... off) {
        Set<ChairSupervisor.Defence> d = all();
        for (ChairSupervisor.Defence x : off) {
            d.remove(x);
        }
        return d;
    }

    @Test
    void anEstopHoldsMotionPastItsReleaseUntilAResume() {
        FakeChair c = new FakeChair();
        Heard heard = new Heard();
        ChairSupervisor s = armedOn(c, all(), heard);
        c.reading(true);
        assertEquals("neutral", c.last());
        assertEquals(List.of("armed by the control agent at start", "hold ESTOP"), heard.said);
        assertNotNull(s.whyNotAvailable(), "no task while the e-stop is held");
        assertTrue(s.resume("operator").contains("e-stop is still pressed"));
        c.reading(false);
        c.event(ChairEvent.Kind.DISARMED, "e-stop");
        // The board is armed again by the host's own neutral heartbeat: not a reason to drive.
        c.event(ChairEvent.Kind.ARMED, null);
        for (int i = 0; i < 5; i++) {
            c.reading(false);
            s.drive(50, 50);
            assertEquals("neutral", c.last(), "released, not resumed: no motion");
        }
        assertTrue(s.whyNotAvailable().contains("waits for an operator's resume"));
        assertNull(s.resume("operator"));
        c.reading(false);
        c.reading(false);
        s.drive(50, 50);
        assertEquals("drive 50,50", c.last());
        assertEquals("armed by operator", heard.said.get(heard.said.size() - 1));
    }

    @Test
    void withoutItsDefencesTheChairDrivesOffWhenTheEstopIsReleased() {
        FakeChair c = new FakeChair();
        ChairSupervisor s = armedOn(c, allBut(ChairSupervisor.Defence.ESTOP_HOLDS, ChairSupervisor.Defence.ARMED_BIT_HOLDS,
                ChairSupervisor.Defence.REFUSAL_HOLDS), new Heard());
        c.reading(true);
        c.event(ChairEvent.Kind.DISARMED, "e-stop");
        assertNull(s.whyNotAvailable(), "the hazard: a task is taken while the e-stop is held");
        c.reading(false);
        c.event(ChairEvent.Kind.ARMED, null);
        s.drive(50, 50);
        assertEquals("drive 50,50", c.last(), "the hazard: motion with nobody's decision");
    }

    @Test
    void aTripTheBoardClearedUnseenIsSeenByItsArmedBit() {
        FakeChair c = new FakeChair();
        Heard heard = new Heard();
        ChairSupervisor s = armedOn(c, all(), heard);
        c.event(ChairEvent.Kind.DISARMED, "watchdog");
        s.drive(50, 50);
        assertEquals("neutral", c.last());
        assertEquals(ChairSupervisor.Cause.WATCHDOG, s.hold().cause());
        assertTrue(s.hold().cause().agentMayResume(), "a trip: the control agent may decide to go on");
        ChairSupervisor off = armedOn(new FakeChair(), allBut(ChairSupervisor.Defence.ARMED_BIT_HOLDS, ChairSupervisor.Defence.REFUSAL_HOLDS),
                new Heard());
        FakeChair oc = (FakeChair) off.chair();
        oc.event(ChairEvent.Kind.DISARMED, "watchdog");
        for (int i = 0; i < 3; i++) {
            oc.event(ChairEvent.Kind.REFUSED, "NAK not neutral for frame " + i);
            off.drive(50, 50);
            assertEquals("drive 50,50", oc.last(), "the hazard: the refused command again and again");
        }
    }

    @Test
    void aRefusalHoldsAndTheBoardsReasonWhenItComesReplacesIt() {
        FakeChair c = new FakeChair();
        Heard heard = new Heard();
        ChairSupervisor s = armedOn(c, all(), heard);
        c.event(ChairEvent.Kind.REFUSED, "NAK not neutral for frame 812");
        assertEquals(ChairSupervisor.Cause.REFUSED, s.hold().cause());
        c.event(ChairEvent.Kind.REFUSED, "NAK not neutral for frame 813");
        assertEquals(List.of("armed by the control agent at start", "hold REFUSED"), heard.said, "held once, whatever the NAKs");
        c.event(ChairEvent.Kind.DISARMED, "watchdog");
        assertEquals(ChairSupervisor.Cause.WATCHDOG, s.hold().cause(), "the board said why");
        assertEquals(2L, s.counts().get("refused"));
    }

    @Test
    void aRebootHoldsForAnOperatorAndWithoutItsDefenceIsIgnored() {
        FakeChair c = new FakeChair();
        ChairSupervisor s = armedOn(c, all(), new Heard());
        c.event(ChairEvent.Kind.REBOOTED, "boot 8 after boot 7");
        c.event(ChairEvent.Kind.DISARMED, "switch-on");
        assertEquals(ChairSupervisor.Cause.REBOOT, s.hold().cause());
        assertTrue(!s.hold().cause().agentMayResume());
        FakeChair oc = new FakeChair();
        ChairSupervisor off = armedOn(oc, allBut(ChairSupervisor.Defence.REBOOT_HOLDS, ChairSupervisor.Defence.ARMED_BIT_HOLDS,
                ChairSupervisor.Defence.REFUSAL_HOLDS), new Heard());
        oc.event(ChairEvent.Kind.REBOOTED, "boot 8 after boot 7");
        off.drive(50, 50);
        assertEquals("drive 50,50", oc.last());
    }

    @Test
    void aLinkThatComesBackHoldsUntilResumedAndWithoutItsDefenceDrivesAtOnce() {
        FakeChair c = new FakeChair();
        Heard heard = new Heard();
        ChairSupervisor s = armedOn(c, all(), heard);
        c.online = false;
        c.listener.onOnline(false);
        assertEquals(ChairSupervisor.State.OFFLINE, s.state());
        assertTrue(s.resume("operator").contains("offline"));
        c.online = true;
        c.listener.onOnline(true);
        s.drive(50, 50);
        assertEquals("neutral", c.last());
        assertEquals(ChairSupervisor.Cause.LINK, s.hold().cause());
        FakeChair oc = new FakeChair();
        ChairSupervisor off = armedOn(oc, allBut(ChairSupervisor.Defence.LINK_HOLDS), new Heard());
        oc.online = false;
        oc.listener.onOnline(false);
        oc.online = true;
        oc.listener.onOnline(true);
        off.drive(50, 50);
        assertEquals("drive 50,50", oc.last());
    }

    /**
     * An operator's stop (the console's Stop all) holds an armed chair as an e-stop does: the agent
     * may not resume it, not even after a link lost and found meanwhile; a chair offline when
     * stopped is held so when its link is back; the operator's resume releases it.
     */
    @Test
    void anOperatorsStopHoldsUntilAnOperatorResumesAcrossALinkLostAndFound() {
        FakeChair c = new FakeChair();
        ChairSupervisor s = armedOn(c, all(), new Heard());
        s.holdByOperator("stop all by operator nurse Ada");
        assertEquals(ChairSupervisor.State.HELD, s.state());
        assertEquals("an operator stopped it (stop all by operator nurse Ada)", s.hold().toString());
        assertFalse(s.hold().agentMayResume());
        s.drive(50, 50);
        assertEquals("neutral", c.last());
        c.online = false;
        c.listener.onOnline(false);
        c.online = true;
        c.listener.onOnline(true);
        assertEquals(ChairSupervisor.State.HELD, s.state());
        assertFalse(s.hold().agentMayResume(), "a link lost and found does not let the agent resume an operator's stop: " + s.hold());
        assertTrue(s.hold().toString().contains("stopped by an operator before (stop all by operator nurse Ada)"), s.hold().toString());
        assertNull(s.resume("operator nurse Ada"));
        assertNull(s.operatorStop());
        c.event(ChairEvent.Kind.ARMED, null);
        c.reading(false);
        c.reading(false);
        s.drive(50, 50);
        assertEquals("drive 50,50", c.last());
        // Offline when stopped: held for an operator once the link is back.
        c.online = false;
        c.listener.onOnline(false);
        s.holdByOperator("stop all by operator nurse Ada");
        c.online = true;
        c.listener.onOnline(true);
        assertEquals(ChairSupervisor.State.HELD, s.state());
        assertFalse(s.hold().agentMayResume(), s.hold().toString());
    }

    // ---- faults that recur -----------------------------------------------------------------------

    /**
     * The link goes down with the driver's reason, comes back 50.5 s later on the clock, and the
     * agent resumes if the hold lets it (as the control agent decides): the hold after the loss.
     */
    private static ChairSupervisor.Hold linkLostAndBack(FakeChair c, ChairSupervisor s, ManualClock clock) {
        c.event(ChairEvent.Kind.LINK_LOST, "every frame stale: the board's clock drifts more than 2 % (3.0 % slow)");
        c.online = false;
        c.listener.onOnline(false);
        assertTrue(c.motionHeld, "the driver is told to forget its command at once");
        clock.advanceNs(50_500_000_000L);
        c.online = true;
        c.listener.onOnline(true);
        ChairSupervisor.Hold h = s.hold();
        if (h.agentMayResume()) {
            assertNull(s.resume("the control agent"));
            c.event(ChairEvent.Kind.ARMED, null);
            c.reading(false);
            c.reading(false);
            assertEquals(ChairSupervisor.State.ARMED, s.state());
            assertTrue(!c.motionHeld, "released when armed again");
        }
        return h;
    }

    @Test
    void aLinkLostThreeTimesWithinTenMinutesHoldsTheChairForAnOperatorWithTheReason() {
        FakeChair c = new FakeChair();
        ManualClock clock = new ManualClock();
        ChairSupervisor s = armedOn(c, all(), new Heard(), clock);
        assertTrue(linkLostAndBack(c, s, clock).agentMayResume(), "the first loss: the agent resumes");
        assertTrue(linkLostAndBack(c, s, clock).agentMayResume(), "the second");
        ChairSupervisor.Hold third = linkLostAndBack(c, s, clock);
        assertEquals(ChairSupervisor.Cause.LINK, third.cause());
        assertEquals("the 3rd link loss within 10 minutes", third.repeated());
        assertTrue(!third.agentMayResume(), "the third within 10 minutes: an operator's");
        assertEquals("the link to the chair went down (every frame stale: the board's clock drifts more than 2 % (3.0 % slow)); the 3rd"
                + " link loss within 10 minutes: an operator must resume it", third.toString());
        assertEquals(ChairSupervisor.State.HELD, s.state());
        s.drive(50, 50);
        assertEquals("neutral", c.last());
        assertTrue(s.whyNotAvailable().contains("waits for an operator's resume"), s.whyNotAvailable());
        assertEquals(1L, s.counts().get("repeated"));
        assertNull(s.resume("nurse Ada"));
        c.event(ChairEvent.Kind.ARMED, null);
        c.reading(false);
        c.reading(false);
        s.drive(50, 50);
        assertEquals("drive 50,50", c.last(), "the operator resumed it");
        assertTrue(linkLostAndBack(c, s, clock).agentMayResume(), "after an operator's decision the count starts again");
    }

    @Test
    void linkLossesFurtherApartThanTheWindowAreResumedByTheAgent() {
        FakeChair c = new FakeChair();
        ManualClock clock = new ManualClock();
        ChairSupervisor s = armedOn(c, all(), new Heard(), clock);
        for (int i = 0; i < 6; i++) {
            clock.advanceNs(250_000_000_000L); // each loss 300.5 s after the last: two in any 10 minutes
            assertTrue(linkLostAndBack(c, s, clock).agentMayResume(), "loss " + (i + 1));
        }
    }

    @Test
    void withoutItsDefenceALinkLostOverAndOverIsResumedByTheAgentForEver() {
        FakeChair c = new FakeChair();
        ManualClock clock = new ManualClock();
        ChairSupervisor s = armedOn(c, allBut(ChairSupervisor.Defence.REPEATS_NEED_OPERATOR), new Heard(), clock);
        for (int i = 0; i < 10; i++) {
            assertTrue(linkLostAndBack(c, s, clock).agentMayResume(), "the hazard: loss " + (i + 1) + " resumed by the agent");
        }
        assertEquals(10L, s.counts().get("link-down"));
    }

    /** A frozen host is a busy machine: the hold is the agent's to end, every time (slow is not dead). */
    @Test
    void aHostFrozenHoldsMotionAndTheAgentResumesItEveryTime() {
        FakeChair c = new FakeChair();
        ManualClock clock = new ManualClock();
        Heard heard = new Heard();
        ChairSupervisor s = armedOn(c, all(), heard, clock);
        for (int i = 1; i <= 5; i++) {
            c.event(ChairEvent.Kind.HOST_FROZEN, "the heartbeat ran 172 ms after its last");
            assertEquals(ChairSupervisor.Cause.HOST_FROZEN, s.hold().cause());
            assertEquals("hold HOST_FROZEN", heard.said.get(heard.said.size() - 1));
            s.drive(50, 50);
            assertEquals("neutral", c.last(), "held: neutral only");
            assertTrue(s.hold().agentMayResume(), s.hold().toString());
            assertNull(s.hold().repeated(), "freeze " + i + " is not a recurring fault of the chair");
            assertNull(s.resume("the control agent"));
            c.event(ChairEvent.Kind.ARMED, null);
            c.reading(false);
            c.reading(false);
            s.drive(50, 50);
            assertEquals("drive 50,50", c.last());
            clock.advanceNs(60_000_000_000L);
        }
        assertEquals(5L, s.counts().get("host-frozen"));
    }
}
