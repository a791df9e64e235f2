package io.concord.serial;

import io.concord.agents.chair.ChairEvent;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.core.agent.AgentRuntime;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.VirtualNetwork;
import io.concord.core.time.ManualClock;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The host driver's watchdog on the link to the board (docs/chair-protocol.md, "The host's side";
 * docs/chair-safety.md, layer 2), on a manual clock: a {@link SerialChair} whose threads are not
 * started, a stand-in for the port, a board played by the test, and the runtime's loop run by the
 * test. Each test moves the clock and takes one heartbeat step at the times that decide a rule:
 * no sleep, no real time.
 *
 * <ul>
 *   <li>The board's STATEs may come up to 500 ms apart; one more millisecond of silence is the
 *       link down: the port closed, a last reading with the LINK fault, offline, nothing sent.</li>
 *   <li>When the port opens again, the session starts anew (a SYNC PING, then CONFIGURE) and the
 *       chair is online at the board's first STATE.</li>
 *   <li>The command goes out again every heartbeat while the agents confirmed it within 300 ms;
 *       past that, one STOP and silence, until the agents confirm a command again.</li>
 *   <li>A stop is one STOP, then neutral DRIVEs at each heartbeat.</li>
 *   <li>Every hold (a new session, a lost link, the supervisor's, a frozen host) clears the
 *       command: only neutral goes out until the supervisor resumes, even when the port reopens
 *       before the supervisor's hold reaches the driver.</li>
 *   <li>Nothing sent for over 150 ms (the host frozen): the command from before is never sent.</li>
 *   <li>A link lost to stale frames says so, with the board's clock drift measured; a silent
 *       board is silent.</li>
 * </ul>
 */
class SerialChairWatchdogTest {
    private static final long HEARTBEAT_MS = 50;
    private static final long SILENT_MS = 500;
    private static final long DEADLINE_MS = 300;
    private static final long FROZEN_MS = 150;

    private final ManualClock clock = new ManualClock();
    private final AgentRuntime runtime = AgentRuntime.builder().clock(clock)
            .network(new VirtualNetwork(new SplittableRandom(1), FaultPlan.NONE, clock)).build();
    private final FrameCodec codec = new FrameCodec();
    /** What the chair told its listener, in order. */
    private final List<String> heard = new ArrayList<>();
    /** Every port the driver opened, the last one in use. */
    private final List<FakePort> ports = new ArrayList<>();
    private SerialChair chair;
    private int boardSeq;

    /** The board's end of the wire: what the host wrote, as frames. The test feeds the host itself. */
    private final class FakePort implements BoardLink {
        final List<Frame> sent = new ArrayList<>();
        boolean closed;
        private final Deframer deframer = new Deframer(1024, b -> sent.add(codec.decode(b, 0, b.length)), () -> {
            throw new AssertionError("the host wrote an oversized frame");
        });

        @Override
        public int read(byte[] buf) {
            throw new AssertionError("no reader thread here: the test feeds the host");
        }

        @Override
        public boolean write(byte[] frame) {
            deframer.feed(frame, 0, frame.length);
            return !closed;
        }

        @Override
        public void close() {
            closed = true;
        }

        /** The frames written since the last call, each as its type's name (DRIVE as its two per mille). */
        List<String> take() {
            List<String> out = new ArrayList<>();
            for (Frame f : sent) {
                String name = Frame.Type.name(f.type());
                if (f.type() == Frame.Type.DRIVE) {
                    int[] d = BoardProtocol.readDrive(f);
                    name += " " + d[0] + "," + d[1];
                }
                out.add((f.flags() & Frame.SYNC) != 0 ? name + " SYNC" : name);
            }
            sent.clear();
            return out;
        }
    }

    @BeforeEach
    void openTheLink() {
        openWith(EnumSet.allOf(SerialChair.Defence.class));
    }

    /** A new driver with these defences, its link open, the board's first STATE taken, motion released as the supervisor would. */
    private void openWith(Set<SerialChair.Defence> defences) {
        ports.clear();
        heard.clear();
        clock.setNanoTime(0);
        boardSeq = 0;
        SerialChair.Settings s = SerialChair.Settings.of("test-port", "chair1");
        assertEquals(HEARTBEAT_MS, s.heartbeatMs());
        assertEquals(SILENT_MS, s.silentMs());
        assertEquals(DEADLINE_MS, s.commandDeadlineMs());
        assertEquals(FROZEN_MS, s.frozenMs());
        chair = new SerialChair(runtime, s, clock, () -> {
            FakePort p = new FakePort();
            ports.add(p);
            return p;
        }, defences);
        chair.setListener(new ChairListener() {
            @Override
            public void onReadings(ChairReadings r) {
                heard.add(r.faults().contains(ChairFault.LINK) ? "reading LINK" : "reading");
            }

            @Override
            public void onOnline(boolean online) {
                heard.add(online ? "online" : "offline");
            }

            @Override
            public void onEvent(ChairEvent e) {
                if (e.kind() == ChairEvent.Kind.LINK_LOST || e.kind() == ChairEvent.Kind.HOST_FROZEN) {
                    heard.add(e.toString());
                }
            }
        });
        assertTrue(chair.openPort());
        boardSays();
        assertEquals(List.of("online", "reading"), heard);
        heard.clear();
        assertTrue(chair.motionHeld(), "a new session holds motion until the supervisor resumes");
        chair.releaseMotion(); // as the supervisor does once the board says it is armed
        assertEquals(List.of(), port().take(), "nothing to send before the agents or the heartbeat ask");
    }

    @AfterEach
    void close() {
        runtime.close();
    }

    private FakePort port() {
        return ports.get(ports.size() - 1);
    }

    /** The board sends a STATE now (armed, nothing in range), and the loop takes it. */
    private void boardSays() {
        boardSays(clock.nanoTime() / 1_000_000);
    }

    /** The board sends a STATE stamped {@code nowMs} on its own clock, and the loop takes it. */
    private void boardSays(long nowMs) {
        int sensors = ChairLayout.standard().sensors().size();
        byte[] body = BoardProtocol.state(new BoardProtocol.State(1, 0, 0, new int[sensors], false, false, true,
                BoardProtocol.ARMED, 24_000, Set.of(), null));
        byte[] b = codec.encode(new Frame(Frame.Type.STATE, 0, boardSeq++ & 0xFFFF, nowMs, body));
        chair.onBytes(b, b.length);
        runtime.doWork();
    }

    /** The clock moves to {@code ms}; the heartbeat thread wakes there; the loop runs what it was handed. */
    private void beatAt(long ms) {
        clock.setNanoTime(ms * 1_000_000);
        chair.beat(clock.nanoTime());
        runtime.doWork();
    }

    /** The agents confirm a command at {@code ms}, as the control agent does on each of its cycles. */
    private void agentsDriveAt(long ms, double left, double right) {
        clock.setNanoTime(ms * 1_000_000);
        chair.drive(left, right);
    }

    // ---- the board's silence -------------------------------------------------------------------

    @Test
    void aBoardSilentForExactlyTheLimitKeepsTheLink() {
        beatAt(SILENT_MS);
        assertFalse(port().closed, "500 ms since the last STATE is not yet the link down");
        assertTrue(chair.online());
        assertEquals(List.of(), heard);
        boardSays();
        beatAt(SILENT_MS + SILENT_MS);
        assertFalse(port().closed, "the silence counts from the board's last frame");
        assertTrue(chair.online());
    }

    @Test
    void aBoardSilentForMoreThanTheLimitIsTheLinkDown() {
        agentsDriveAt(0, 20, 20);
        assertEquals(List.of("PING SYNC", "CONFIGURE", "DRIVE 200,200"), port().take());
        for (long ms = HEARTBEAT_MS; ms <= SILENT_MS; ms += HEARTBEAT_MS) {
            agentsDriveAt(ms, 20, 20);
            beatAt(ms);
        }
        assertFalse(port().closed);
        port().take();
        agentsDriveAt(SILENT_MS + 1, 20, 20);
        beatAt(SILENT_MS + 1);
        assertTrue(port().closed, "501 ms without a frame from the board: the port is closed");
        assertFalse(chair.online());
        assertEquals(List.of("LINK_LOST (the board has been silent for 501 ms)", "reading LINK", "offline"), heard,
                "why, then a last reading with the LINK fault, then offline");
        assertEquals(List.of(), port().take(), "the heartbeat sent nothing on a link it took for lost");
        agentsDriveAt(SILENT_MS + 40, 20, 30);
        beatAt(SILENT_MS + 51);
        assertEquals(List.of(), port().take(), "nothing is written while the link is down");
        assertEquals(1, ports.size());
    }

    @Test
    void whenTheLinkComesBackANewSessionStartsAndTheChairIsOnlineAtTheBoardsFirstState() {
        beatAt(HEARTBEAT_MS);
        assertEquals(List.of("PING SYNC", "CONFIGURE", "STOP"), port().take(), "the first session");
        beatAt(SILENT_MS + 1);
        assertEquals(List.of("LINK_LOST (the board has been silent for 501 ms)", "reading LINK", "offline"), heard);
        heard.clear();
        assertEquals(1, chair.reconnects());
        // The reader opens the port again (after its back-off); the agents want the chair to stand.
        clock.setNanoTime(2_000_000_000L);
        assertTrue(chair.openPort());
        assertEquals(2, ports.size());
        agentsDriveAt(2_000, 0, 0);
        beatAt(2_050);
        assertEquals(List.of("PING SYNC", "CONFIGURE", "STOP"), port().take(),
                "a new session first: the board disarms on the SYNC and counts the host's frames afresh");
        assertFalse(chair.online(), "online only once the board speaks");
        boardSays();
        assertEquals(List.of("online", "reading"), heard);
        assertEquals(2, chair.reconnects());
        agentsDriveAt(2_090, 0, 0);
        beatAt(2_100);
        assertEquals(List.of("DRIVE 0,0"), port().take());
    }

    // ---- the agents' silence: the stop sent ----------------------------------------------------

    @Test
    void whileTheAgentsConfirmTheCommandTheHeartbeatRepeatsItEveryBeat() {
        agentsDriveAt(0, 50, -50);
        assertEquals(List.of("PING SYNC", "CONFIGURE", "DRIVE 500,-500"), port().take(), "a changed command goes out at once");
        for (long ms = HEARTBEAT_MS; ms <= 10_000; ms += HEARTBEAT_MS) {
            agentsDriveAt(ms - 10, 50, -50);
            if (ms % 250 == 0) {
                boardSays();
            }
            beatAt(ms);
            assertEquals(List.of("DRIVE 500,-500"), port().take(), "at " + ms + " ms");
        }
        double[] gaps = chair.heartbeatGapsMs();
        assertEquals(199, gaps.length);
        for (double g : gaps) {
            assertEquals(HEARTBEAT_MS, g, 1e-9);
        }
    }

    @Test
    void aCommandTheAgentsStopConfirmingIsStoppedOnceAfterTheDeadlineThenTheHeartbeatFallsSilent() {
        agentsDriveAt(0, 50, 50);
        port().take();
        for (long ms = HEARTBEAT_MS; ms <= DEADLINE_MS; ms += HEARTBEAT_MS) {
            beatAt(ms);
            assertEquals(List.of("DRIVE 500,500"), port().take(), ms + " ms since the agents confirmed it: still sent");
        }
        beatAt(DEADLINE_MS + 1);
        assertEquals(List.of("STOP"), port().take(), "301 ms: one STOP");
        for (long ms = DEADLINE_MS + HEARTBEAT_MS; ms <= 1_000; ms += HEARTBEAT_MS) {
            if (ms % 250 == 0) {
                boardSays(); // the board still talks: the link is up, only the host is silent
            }
            beatAt(ms);
            assertEquals(List.of(), port().take(), "silence at " + ms + " ms, so that the board's watchdog trips");
        }
        assertFalse(port().closed);
        assertTrue(chair.online());
    }

    @Test
    void aCommandConfirmedAgainAfterTheStopGoesOutAtOnceAndTheHeartbeatResumes() {
        agentsDriveAt(0, 50, 50);
        beatAt(DEADLINE_MS + 1);
        boardSays();
        beatAt(400);
        port().take();
        agentsDriveAt(420, 50, 50);
        assertEquals(List.of("DRIVE 500,500"), port().take(), "the same command, confirmed after it expired, goes out at once");
        beatAt(450);
        assertEquals(List.of("DRIVE 500,500"), port().take());
    }

    @Test
    void aStandStillConfirmedAfterTheStopRestartsTheHeartbeat() {
        agentsDriveAt(0, 50, 50);
        beatAt(DEADLINE_MS + 1);
        boardSays();
        port().take();
        clock.setNanoTime(420_000_000);
        chair.stop();
        assertEquals(List.of("DRIVE 0,0"), port().take(), "neutral, confirmed after the command expired, goes out at once");
        beatAt(450);
        assertEquals(List.of("DRIVE 0,0"), port().take(), "and with every heartbeat after");
    }

    @Test
    void aStopIsOneStopThenNeutralDrivesAtEachHeartbeat() {
        agentsDriveAt(0, 30, 30);
        port().take();
        clock.setNanoTime(10_000_000);
        chair.stop();
        assertEquals(List.of("STOP"), port().take());
        for (long ms = HEARTBEAT_MS; ms <= 200; ms += HEARTBEAT_MS) {
            clock.setNanoTime(ms * 1_000_000 - 1);
            chair.stop();
            beatAt(ms);
            assertEquals(List.of("DRIVE 0,0"), port().take(), "at " + ms + " ms");
        }
    }

    // ---- holds: only neutral until the supervisor resumes ----------------------------------------

    /**
     * The race of issue 51: the board falls silent mid-drive, the link goes down, and the agents
     * confirm their drive once more before the supervisor's hold reaches the driver; the port opens
     * again at once. What the board gets on the new session.
     */
    private List<String> reconnectedWhileTheAgentsStillDrive() {
        agentsDriveAt(0, 60, 60);
        assertEquals(List.of("PING SYNC", "CONFIGURE", "DRIVE 600,600"), port().take());
        for (long ms = HEARTBEAT_MS; ms <= SILENT_MS; ms += HEARTBEAT_MS) {
            agentsDriveAt(ms - 10, 60, 60);
            beatAt(ms);
        }
        beatAt(SILENT_MS + 1);
        assertTrue(port().closed, "the link is down");
        agentsDriveAt(SILENT_MS + 2, 60, 60);  // the agents' loop, not yet told
        clock.setNanoTime((SILENT_MS + 3) * 1_000_000);
        assertTrue(chair.openPort());          // the reader opens the port again at once
        beatAt(SILENT_MS + 20);                // the heartbeat, before the loop runs the hold
        return port().take();
    }

    @Test
    void aReconnectWhileTheAgentsStillDriveSendsOnlyNeutralUntilTheSupervisorResumes() {
        assertEquals(List.of("PING SYNC", "CONFIGURE", "STOP"), reconnectedWhileTheAgentsStillDrive(),
                "the new session's third frame is neutral: the lost link cleared the command");
        assertTrue(chair.motionHeld());
        for (long ms = 550; ms <= 1_000; ms += HEARTBEAT_MS) {
            agentsDriveAt(ms - 5, 60, 60);     // the agents ask on; a supervisor would not even pass it
            if (ms % 100 == 0) {
                boardSays();
            }
            beatAt(ms);
            assertEquals(List.of("DRIVE 0,0"), port().take(), "only neutral while held, at " + ms + " ms");
        }
        chair.releaseMotion();                 // the supervisor resumed: the board said armed twice
        assertEquals(List.of(), port().take(), "a command given while held is not kept for after the resume");
        agentsDriveAt(1_010, 60, 60);
        assertEquals(List.of("DRIVE 600,600"), port().take(), "the agents' next command drives");
    }

    @Test
    void withoutItsDefenceAReconnectSendsTheLastDriveAsTheNewSessionsThirdFrame() {
        openWith(EnumSet.complementOf(EnumSet.of(SerialChair.Defence.NEUTRAL_UNTIL_RESUMED)));
        assertEquals(List.of("PING SYNC", "CONFIGURE", "DRIVE 600,600"), reconnectedWhileTheAgentsStillDrive(),
                "the hazard: a board that missed the SYNC drives on a command from before the link was lost");
    }

    @Test
    void theSupervisorsHoldSendsStopAtOnceAndNeutralAfter() {
        agentsDriveAt(0, 60, 60);
        port().take();
        clock.setNanoTime(20_000_000);
        chair.holdMotion();
        assertEquals(List.of("STOP"), port().take());
        agentsDriveAt(30, 60, 60);
        beatAt(50);
        assertEquals(List.of("DRIVE 0,0"), port().take());
    }

    // ---- a host frozen mid-drive ---------------------------------------------------------------

    /** Driving at 600,600, confirmed on every reading, then the whole host stops for 170 ms after the beat at 200 ms. */
    private void drivingThenFrozenFor170Ms() {
        agentsDriveAt(0, 60, 60);
        port().take();
        for (long ms = HEARTBEAT_MS; ms <= 200; ms += HEARTBEAT_MS) {
            agentsDriveAt(ms - 10, 60, 60);
            boardSays();
            beatAt(ms);
        }
        assertEquals(List.of("DRIVE 600,600", "DRIVE 600,600", "DRIVE 600,600", "DRIVE 600,600"), port().take());
        heard.clear();
        // Frozen from 200 to 370 ms: nothing runs. The board has not tripped (170 ms < 200 ms).
    }

    @Test
    void aHostFrozenFor170MsNeverSendsTheCommandFromBeforeTheFreeze() {
        drivingThenFrozenFor170Ms();
        beatAt(370);  // the heartbeat wakes first: the command was confirmed 180 ms ago, within the deadline
        assertEquals(List.of("STOP"), port().take(), "the first frame after the freeze is neutral");
        assertEquals(List.of("HOST_FROZEN (nothing was sent to the board for 170 ms (over 150 ms: the host was frozen or late);"
                + " the command it held, confirmed 180 ms ago, is not sent)"), heard);
        assertEquals(1, chair.frozen());
        agentsDriveAt(375, 60, 60);
        beatAt(420);
        assertEquals(List.of("DRIVE 0,0"), port().take(), "held until the supervisor resumes");
        chair.releaseMotion();
        agentsDriveAt(430, 60, 60);
        assertEquals(List.of("DRIVE 600,600"), port().take());
    }

    @Test
    void aHostFrozenFor170MsWhoseLoopWakesFirstSendsNeutralToo() {
        drivingThenFrozenFor170Ms();
        agentsDriveAt(370, 70, 70);  // the loop wakes first, with a new command from a reading before the freeze
        assertEquals(List.of("STOP"), port().take());
        assertEquals(1, chair.frozen());
    }

    @Test
    void withoutItsDefenceTheFirstFrameAfterAFreezeIsTheFrozenCommand() {
        openWith(EnumSet.complementOf(EnumSet.of(SerialChair.Defence.NO_FROZEN_COMMAND)));
        drivingThenFrozenFor170Ms();
        beatAt(370);
        assertEquals(List.of("DRIVE 600,600"), port().take(), "the hazard: a 180 ms old command to a board that has not tripped");
        assertEquals(0, chair.frozen());
    }

    // ---- a link lost to stale frames --------------------------------------------------------------

    @Test
    void aLinkLostToStaleFramesSaysTheBoardsClockDriftsAndByHowMuch() {
        long lastBeat = 0;
        for (long ms = HEARTBEAT_MS; ms <= 60_000 && !port().closed; ms += HEARTBEAT_MS) {
            clock.setNanoTime(ms * 1_000_000 - 1_000_000);
            chair.stop();
            boardSays(Math.round(ms * 0.97));  // the board's clock 3 % slow
            beatAt(ms);
            lastBeat = ms;
        }
        assertTrue(port().closed, "the link is lost");
        // The delay grows by 1 % of the time passed (3 % less the 2 % tolerated): over 500 ms after 50 s.
        assertTrue(lastBeat > 50_000 && lastBeat < 51_500, "lost at " + lastBeat + " ms");
        String lost = heard.stream().filter(h -> h.startsWith("LINK_LOST")).findFirst().orElseThrow(() -> new AssertionError(heard));
        assertTrue(lost.startsWith("LINK_LOST (every frame stale: the board's clock drifts more than 2 % (3.0 % slow, measured over 5"),
                lost);
        assertTrue(lost.contains(" frames in 5") && lost.endsWith(" ms were dropped as over 500 ms late)"), lost);
        assertEquals(0.03, chair.drift(), 0.001);
        assertTrue(chair.drops().get("stale") >= 10, chair.drops().toString());
    }

    @Test
    void aBoardThatSaysNothingIsSilentNotStale() {
        beatAt(SILENT_MS + 1);
        assertEquals(List.of("LINK_LOST (the board has been silent for 501 ms)", "reading LINK", "offline"), heard);
    }
}
