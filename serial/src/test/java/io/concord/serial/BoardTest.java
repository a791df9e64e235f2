package io.concord.serial;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Pose;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The board's safety rules, frame by frame, on the board's own clock. */
class BoardTest {

    /** Motors that remember what they were told. */
    static final class Motors implements ChairDriver {
        double left;
        double right;

        @Override
        public String name() {
            return "chair";
        }

        @Override
        public ChairLayout layout() {
            return ChairLayout.standard();
        }

        @Override
        public void drive(double l, double r) {
            left = l;
            right = r;
        }

        @Override
        public ChairReadings latest() {
            return new ChairReadings(0, 0, 0, 0, new double[ChairLayout.standard().sensors().size()], false, 24, false, Set.of(),
                    new Pose(0, 0, 0), null);
        }

        @Override
        public boolean online() {
            return true;
        }

        @Override
        public void setListener(ChairListener l) {
        }
    }

    /** A board with a host that speaks to it; the board's frames are kept. */
    static final class Bench {
        final Motors motors = new Motors();
        final FrameCodec codec = new FrameCodec();
        final List<Frame> fromBoard = new ArrayList<>();
        final Deframer deframer = new Deframer(2048, s -> fromBoard.add(codec.decode(s, 0, s.length)), () -> { });
        final Board board = new Board(motors, codec, "test", b -> deframer.feed(b, 0, b.length));
        int seq;
        long now;

        Bench() {
            board.switchOn(0);
        }

        /** The supervisor's resume: an ARM for the board's state as it is now (as its last STATE would show it). */
        void arm() {
            host(Frame.Type.ARM, 0, BoardProtocol.arm(board.boot(), board.disarmedBy()));
        }

        void host(int type, int flags, byte[] body) {
            byte[] b = codec.encode(new Frame(type, flags, seq++, now, body));
            board.onBytes(b, 0, b.length, now);
        }

        void drive(int l, int r) {
            host(Frame.Type.DRIVE, 0, BoardProtocol.drive(l, r));
        }

        void at(long ms) {
            now = ms;
            board.tick(ms);
        }

        List<Integer> naks() {
            List<Integer> out = new ArrayList<>();
            for (Frame f : fromBoard) {
                if (f.type() == Frame.Type.NAK) {
                    Frame.Fields r = f.fields();
                    r.u16();
                    out.add(r.u8());
                }
            }
            return out;
        }

        BoardProtocol.State lastState() {
            for (int i = fromBoard.size() - 1; i >= 0; i--) {
                if (fromBoard.get(i).type() == Frame.Type.STATE) {
                    return BoardProtocol.readState(fromBoard.get(i));
                }
            }
            throw new AssertionError("no STATE");
        }
    }

    @Test
    void atSwitchOnANonNeutralDriveIsRefusedUntilAnArm() {
        Bench b = new Bench();
        assertEquals(Frame.Type.HELLO, b.fromBoard.get(0).type(), "HELLO at switch-on");
        b.drive(500, 500);
        assertEquals(0.0, b.motors.left);
        assertEquals(List.of(BoardProtocol.NAK_NOT_ARMED), b.naks());
        b.host(Frame.Type.STOP, 0, new byte[0]);
        b.drive(500, 400);
        assertEquals(0.0, b.motors.left, "a STOP does not arm (version 3)");
        b.arm();
        b.drive(500, 400);
        assertEquals(50.0, b.motors.left);
        assertEquals(40.0, b.motors.right);
    }

    @Test
    void theWatchdogStopsTheMotorsAfter200MsOfSilenceAndDrivingNeedsAnArmAgain() {
        Bench b = new Bench();
        b.arm();
        b.drive(300, 300);
        b.at(150);
        assertEquals(30.0, b.motors.left, "still within 200 ms");
        b.drive(300, 300);
        b.at(350);
        assertEquals(30.0, b.motors.left, "200 ms after the last frame, not more");
        b.at(351);
        assertEquals(0.0, b.motors.left, "stopped 201 ms after the last frame");
        assertTrue(b.board.tripped());
        b.at(400);
        assertTrue(b.lastState().faults().contains(ChairFault.WATCHDOG));
        b.drive(300, 300);
        assertFalse(b.board.tripped(), "a valid frame clears the trip");
        assertEquals(0.0, b.motors.left, "but driving needs an ARM first");
        b.drive(0, 0);
        b.drive(300, 300);
        assertEquals(0.0, b.motors.left, "a neutral DRIVE does not arm");
        b.arm();
        b.drive(300, 300);
        assertEquals(30.0, b.motors.left);
        b.at(450);
        assertFalse(b.lastState().faults().contains(ChairFault.WATCHDOG));
    }

    @Test
    void theEstopWinsOverEverything() {
        Bench b = new Bench();
        b.arm();
        b.drive(600, 600);
        assertEquals(60.0, b.motors.left);
        b.board.estop(true, 10);
        assertEquals(0.0, b.motors.left);
        b.drive(600, 600);
        b.arm();
        b.drive(600, 600);
        assertEquals(0.0, b.motors.left, "no command moves it while the e-stop is pressed");
        assertTrue(b.naks().contains(BoardProtocol.NAK_ESTOP));
        b.at(60);
        assertTrue(b.lastState().estop());
        b.board.estop(false, 70);
        b.drive(600, 600);
        assertEquals(0.0, b.motors.left, "released: an ARM first");
        b.host(Frame.Type.STOP, 0, new byte[0]);
        b.drive(600, 600);
        assertEquals(0.0, b.motors.left, "a STOP does not arm");
        b.arm();
        b.drive(600, 600);
        assertEquals(60.0, b.motors.left);
    }

    @Test
    void aStaleOrRepeatedHostFrameDoesNotDrive() {
        Bench b = new Bench();
        b.arm();
        b.at(100);
        // A DRIVE stamped 300 ms before the host's clock says now: delayed on the way.
        byte[] late = b.codec.encode(new Frame(Frame.Type.DRIVE, 0, b.seq++, -200 & 0xFFFFFFFFL, BoardProtocol.drive(800, 800)));
        b.board.onBytes(late, 0, late.length, 100);
        assertEquals(0.0, b.motors.left);
        assertEquals(1, b.board.drops().get("stale"));
        byte[] once = b.codec.encode(new Frame(Frame.Type.DRIVE, 0, b.seq++, 100, BoardProtocol.drive(200, 200)));
        b.board.onBytes(once, 0, once.length, 100);
        b.host(Frame.Type.STOP, 0, new byte[0]);
        b.board.onBytes(once, 0, once.length, 100);
        assertEquals(0.0, b.motors.left, "the replayed DRIVE after the STOP is not taken");
        assertEquals(1, b.board.drops().get("out-of-order"));
    }

    @Test
    void aMalformedDriveIsRefusedAndChangesNothing() {
        Bench b = new Bench();
        b.arm();
        b.drive(100, 100);
        b.host(Frame.Type.DRIVE, 0, new byte[] {1, 2, 3});
        assertEquals(10.0, b.motors.left);
        assertEquals(List.of(BoardProtocol.NAK_MALFORMED), b.naks());
        assertEquals(1, b.board.drops().get("malformed"));
        assertArrayEquals(new int[] {100, 100}, b.board.motors());
    }

    /** Every STATE says whether the board is armed and, if not, why; a new session does not hide an e-stop. */
    @Test
    void everyStateSaysWhetherItIsArmedAndWhyNot() {
        Bench b = new Bench();
        b.at(0);
        assertFalse(b.lastState().armed());
        assertEquals(BoardProtocol.DISARMED_SWITCH_ON, b.lastState().reason());
        b.arm();
        b.at(50);
        assertTrue(b.lastState().armed());
        assertEquals(BoardProtocol.ARMED, b.lastState().reason());
        b.at(300);
        assertFalse(b.lastState().armed(), "the watchdog tripped");
        assertEquals(BoardProtocol.DISARMED_WATCHDOG, b.lastState().reason());
        b.drive(300, 300);
        b.at(350);
        assertEquals(BoardProtocol.DISARMED_WATCHDOG, b.lastState().reason(), "a frame clears the fault, not the disarm");
        assertFalse(b.lastState().faults().contains(ChairFault.WATCHDOG));
        b.board.estop(true, 360);
        b.board.estop(false, 370);
        b.at(400);
        assertEquals(BoardProtocol.DISARMED_ESTOP, b.lastState().reason(), "an e-stop is the graver reason");
        b.host(Frame.Type.PING, Frame.SYNC, BoardProtocol.ping(1));
        b.at(450);
        assertEquals(BoardProtocol.DISARMED_ESTOP, b.lastState().reason(), "a new session does not hide the e-stop");
    }

    /** A host's new session (SYNC PING) disarms: it never inherits the last session's motion. */
    @Test
    void aSyncDisarmsTheBoard() {
        Bench b = new Bench();
        b.arm();
        b.drive(400, 400);
        assertEquals(40.0, b.motors.left);
        b.host(Frame.Type.PING, Frame.SYNC, BoardProtocol.ping(9));
        assertEquals(0.0, b.motors.left);
        assertFalse(b.board.armed());
        assertEquals(BoardProtocol.DISARMED_SESSION, b.board.disarmedBy());
        b.drive(400, 400);
        assertEquals(0.0, b.motors.left, "driving needs an ARM again");
    }

    /**
     * A SYNC skips the sequence and delay checks, so it is taken on a PING alone (which disarms):
     * a DRIVE flagged SYNC, old and out of order, is dropped as malformed and drives nothing.
     */
    @Test
    void aSyncOnACommandIsMalformedNotASession() {
        Bench b = new Bench();
        b.arm();
        b.at(100);
        b.host(Frame.Type.STOP, 0, new byte[0]);
        byte[] forged = b.codec.encode(new Frame(Frame.Type.DRIVE, Frame.SYNC, 3, 10, BoardProtocol.drive(800, 800)));
        b.board.onBytes(forged, 0, forged.length, 100);
        assertEquals(0.0, b.motors.left, "no motion from a SYNC that is not a PING");
        assertEquals(1, b.board.drops().get("malformed"));
        assertTrue(b.board.armed(), "and no session either: nothing changed");
    }

    /** A reboot: the next boot number, seq 0, counts from 0, not armed. */
    @Test
    void aRebootSaysItsNewBootNumberAndStartsItsCountsAgain() {
        Bench b = new Bench();
        b.host(Frame.Type.STOP, 0, new byte[0]);
        b.at(0);
        assertEquals(1, b.lastState().boot());
        b.fromBoard.clear();
        b.board.switchOn(2, 100);
        Frame hello = b.fromBoard.get(0);
        assertEquals(Frame.Type.HELLO, hello.type());
        assertEquals(0, hello.seq());
        assertEquals(2, BoardProtocol.readHello(hello).boot());
        b.at(100);
        assertEquals(2, b.lastState().boot());
        assertFalse(b.lastState().armed());
        assertEquals(BoardProtocol.DISARMED_SWITCH_ON, b.lastState().reason());
    }

    /**
     * The board's own rule, independent of the host: no neutral command arms it, however many, after
     * switch-on, a watchdog trip, an e-stop's release or a new session; only an ARM for its state.
     * Shown to fail on a board that arms on neutral, as version 2 did (the host's heartbeat re-armed it).
     */
    @Test
    void noHeartbeatArmsTheBoardOnlyAnArm() {
        neutralNeverArms(new Bench());
        Bench v2 = new Bench();
        v2.board.withoutArmStep();
        assertThrows(AssertionError.class, () -> neutralNeverArms(v2), "a board that arms on neutral is re-armed by the heartbeat");
    }

    private static void neutralNeverArms(Bench b) {
        long t = 0;
        for (String after : List.of("switch-on", "watchdog", "e-stop", "new session")) {
            switch (after) {
                case "watchdog" -> {
                    b.arm();
                    assertTrue(b.board.armed(), "armed by the ARM");
                    b.at(t += 250);
                }
                case "e-stop" -> {
                    b.board.estop(true, t += 10);
                    b.board.estop(false, t += 10);
                }
                case "new session" -> {
                    b.arm();
                    b.host(Frame.Type.PING, Frame.SYNC, BoardProtocol.ping(7));
                }
                default -> { }
            }
            // A second of the heartbeat: STOP once, then DRIVE 0, 0 every 50 ms.
            b.host(Frame.Type.STOP, 0, new byte[0]);
            for (int i = 0; i < 20; i++) {
                b.at(t += 50);
                b.drive(0, 0);
            }
            assertFalse(b.board.armed(), "armed by the host's neutral frames after " + after);
            b.drive(300, 300);
            assertEquals(0.0, b.motors.left, "driven after " + after + " with no ARM");
            b.arm();
            b.drive(300, 300);
            assertEquals(30.0, b.motors.left, "the ARM for its state arms it after " + after);
            b.host(Frame.Type.STOP, 0, new byte[0]);
        }
    }

    /** An ARM names the state it was decided on: another boot, another reason, or the e-stop pressed, and it is refused. */
    @Test
    void anArmForAnotherStateIsRefused() {
        Bench b = new Bench();
        b.host(Frame.Type.ARM, 0, BoardProtocol.arm(b.board.boot() + 1, b.board.disarmedBy()));
        b.host(Frame.Type.ARM, 0, BoardProtocol.arm(b.board.boot(), BoardProtocol.DISARMED_WATCHDOG));
        assertFalse(b.board.armed());
        assertEquals(List.of(BoardProtocol.NAK_STALE_ARM, BoardProtocol.NAK_STALE_ARM), b.naks());
        b.board.estop(true, 5);
        b.arm();
        assertFalse(b.board.armed(), "the e-stop is pressed");
        assertEquals(BoardProtocol.NAK_ESTOP, b.naks().get(2));
        b.host(Frame.Type.ARM, 0, BoardProtocol.arm(b.board.boot(), 9));
        assertEquals(BoardProtocol.NAK_MALFORMED, b.naks().get(3), "a reason that is no reason");
        b.board.estop(false, 10);
        b.arm();
        assertTrue(b.board.armed());
        int naks = b.naks().size();
        b.host(Frame.Type.ARM, 0, BoardProtocol.arm(b.board.boot(), BoardProtocol.DISARMED_ESTOP));
        assertTrue(b.board.armed(), "a repeated ARM when armed is only acknowledged");
        assertEquals(naks, b.naks().size());
    }

    /** The state rate: a SYNC keeps what CONFIGURE set; a restart goes back to 20 Hz until configured. */
    @Test
    void theStateRateSurvivesASyncNotARestart() {
        Bench b = new Bench();
        b.host(Frame.Type.CONFIGURE, 0, BoardProtocol.configure(50));
        b.host(Frame.Type.PING, Frame.SYNC, BoardProtocol.ping(3));
        assertEquals(50, states(b, 1_000, 2_000), "50 Hz after the SYNC");
        b.board.switchOn(2, 2_000);
        assertEquals(20, states(b, 2_000, 3_000), "20 Hz after a restart");
    }

    private static int states(Bench b, long from, long to) {
        b.board.tick(from);
        b.fromBoard.clear();
        for (long t = from + 1; t <= to; t++) {
            b.board.tick(t);
        }
        return (int) b.fromBoard.stream().filter(f -> f.type() == Frame.Type.STATE).count();
    }
}
