package io.concord.serial;

import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.Pose;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HexFormat;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The test vectors of docs/chair-protocol.md are what the codec does, both ways. */
class ChairProtocolDocTest {
    private static final HexFormat HEX = HexFormat.of();

    record Vector(String type, int flags, int seq, long time, byte[] body, byte[] key, byte[] raw, byte[] wire) {
    }

    static List<Vector> vectors() throws IOException {
        String doc = Files.readString(Path.of("..", "docs", "chair-protocol.md"));
        Matcher block = Pattern.compile("```vectors\\n(.*?)```", Pattern.DOTALL).matcher(doc);
        assertTrue(block.find(), "the document has a vectors block");
        Pattern head = Pattern.compile("^(\\w+) flags=(\\d+) seq=(\\d+) time=(\\d+) body=([0-9a-f]*)(?: key=([0-9a-f]+))?.*$");
        List<Vector> out = new ArrayList<>();
        String[] lines = block.group(1).split("\\n");
        for (int i = 0; i < lines.length; i++) {
            Matcher m = head.matcher(lines[i]);
            if (!m.matches()) {
                continue;
            }
            byte[] raw = HEX.parseHex(lines[i + 1].replace("raw", "").replace(" ", ""));
            byte[] wire = HEX.parseHex(lines[i + 2].replace("wire", "").replace(" ", ""));
            out.add(new Vector(m.group(1), Integer.parseInt(m.group(2)), Integer.parseInt(m.group(3)), Long.parseLong(m.group(4)),
                    HEX.parseHex(m.group(5)), m.group(6) == null ? null : HEX.parseHex(m.group(6)), raw, wire));
        }
        return out;
    }

    static int type(String name) {
        return switch (name) {
            case "DRIVE" -> Frame.Type.DRIVE;
            case "STOP" -> Frame.Type.STOP;
            case "CONFIGURE" -> Frame.Type.CONFIGURE;
            case "PING" -> Frame.Type.PING;
            case "ARM" -> Frame.Type.ARM;
            case "STATE" -> Frame.Type.STATE;
            case "HELLO" -> Frame.Type.HELLO;
            case "ACK" -> Frame.Type.ACK;
            case "NAK" -> Frame.Type.NAK;
            default -> throw new IllegalArgumentException(name);
        };
    }

    @Test
    void everyVectorEncodesToItsBytesAndDecodesBack() throws IOException {
        List<Vector> vs = vectors();
        assertEquals(14, vs.size(), "the document's vectors");
        for (Vector v : vs) {
            FrameCodec codec = new FrameCodec(v.key());
            Frame f = new Frame(type(v.type()), v.flags(), v.seq(), v.time(), v.body());
            assertArrayEquals(v.raw(), codec.raw(f), v.type() + " raw");
            assertArrayEquals(v.wire(), codec.encode(f), v.type() + " wire");
            Frame back = codec.decode(v.wire(), 0, v.wire().length - 1);
            assertEquals(new Frame(f.type(), f.flags() | (v.key() != null ? Frame.MAC : 0), f.seq(), f.timeMs(), f.body()), back);
        }
    }

    @Test
    void theVectorsBodiesAreWhatTheTypedFieldsWrite() throws IOException {
        List<Vector> vs = vectors();
        assertArrayEquals(vs.get(0).body(), BoardProtocol.drive(500, -250));
        assertArrayEquals(vs.get(2).body(), BoardProtocol.ping(0));
        assertArrayEquals(vs.get(3).body(), BoardProtocol.ping(0xDEADBEEFL));
        assertArrayEquals(vs.get(4).body(), BoardProtocol.configure(20));
        BoardProtocol.State s = new BoardProtocol.State(3, 2048, -1024, new int[] {1500, BoardProtocol.NO_RANGE}, true, false, false,
                BoardProtocol.DISARMED_WATCHDOG, 24_100, EnumSet.of(ChairFault.WATCHDOG), null);
        assertArrayEquals(vs.get(5).body(), BoardProtocol.state(s));
        BoardProtocol.State back = BoardProtocol.readState(new Frame(Frame.Type.STATE, 0, 7, 123_456, vs.get(5).body()));
        assertEquals(3, back.boot());
        assertEquals(2048, back.leftTicks());
        assertEquals(-1024, back.rightTicks());
        assertArrayEquals(new int[] {1500, 0xFFFF}, back.rangesMm());
        assertTrue(back.bumper());
        assertFalse(back.armed());
        assertEquals(BoardProtocol.DISARMED_WATCHDOG, back.reason());
        assertEquals(EnumSet.of(ChairFault.WATCHDOG), back.faults());
        BoardProtocol.State fixed = BoardProtocol.readState(new Frame(Frame.Type.STATE, 0, 8, 123_506, vs.get(6).body()));
        assertTrue(fixed.armed());
        assertEquals(BoardProtocol.ARMED, fixed.reason());
        assertEquals(new Pose(12.345, -6.789, 1.5708), fixed.fix());
        BoardProtocol.Hello h = BoardProtocol.readHello(new Frame(Frame.Type.HELLO, 0, 0, 0, vs.get(7).body()));
        assertEquals(3, h.version());
        assertEquals(3, h.boot());
        assertEquals("fw 3", h.firmware());
        assertEquals("front", h.layout().sensors().get(0).name());
        assertEquals(0.17, h.layout().wheelRadiusM(), 1e-9);
        BoardProtocol.Hello longName = BoardProtocol.readHello(new Frame(Frame.Type.HELLO, 0, 0, 0, vs.get(8).body()));
        assertEquals("x".repeat(250), longName.firmware());
        assertEquals((byte) 0xFF, vs.get(8).wire()[8], "the 254-byte block's code");
        assertArrayEquals(vs.get(9).body(), BoardProtocol.ack(3, 0));
        assertArrayEquals(vs.get(10).body(), BoardProtocol.nak(4, BoardProtocol.NAK_NOT_ARMED, BoardProtocol.DISARMED_WATCHDOG));
        assertEquals(new BoardProtocol.Nak(4, BoardProtocol.NAK_NOT_ARMED, BoardProtocol.DISARMED_WATCHDOG),
                BoardProtocol.readNak(new Frame(Frame.Type.NAK, 0, 9, 123_470, vs.get(10).body())));
        assertArrayEquals(vs.get(11).body(), BoardProtocol.arm(3, BoardProtocol.DISARMED_ESTOP));
        assertEquals(new BoardProtocol.Arm(3, BoardProtocol.DISARMED_ESTOP),
                BoardProtocol.readArm(new Frame(Frame.Type.ARM, 0, 12, 5_200, vs.get(11).body())));
        assertArrayEquals(vs.get(12).body(), BoardProtocol.nak(12, BoardProtocol.NAK_STALE_ARM, BoardProtocol.DISARMED_SWITCH_ON));
        assertEquals(1, vs.get(13).raw()[1], "the keyed vector's flags byte has the MAC bit");
    }

    @Test
    void aStateThatContradictsItselfIsMalformed() {
        BoardProtocol.State s = new BoardProtocol.State(3, 0, 0, new int[0], false, false, true, BoardProtocol.DISARMED_WATCHDOG, 24_000,
                EnumSet.noneOf(ChairFault.class), null);
        FrameException e = org.junit.jupiter.api.Assertions.assertThrows(FrameException.class,
                () -> BoardProtocol.readState(new Frame(Frame.Type.STATE, 0, 1, 0, BoardProtocol.state(s))));
        assertEquals("malformed", e.reason());
    }

    @Test
    void theCrcAndCobsFactsOfTheDocument() {
        java.util.zip.CRC32C crc = new java.util.zip.CRC32C();
        crc.update("123456789".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        assertEquals(0xE3069283L, crc.getValue());
        assertArrayEquals(HEX.parseHex("0101"), Cobs.encode(new byte[] {0}, 0, 1));
        assertArrayEquals(HEX.parseHex("0311220233"), Cobs.encode(HEX.parseHex("11220033"), 0, 4));
        byte[] run = new byte[254];
        for (int i = 0; i < run.length; i++) {
            run[i] = (byte) (i + 1);
        }
        byte[] e = Cobs.encode(run, 0, run.length);
        assertEquals(255, e.length);
        assertEquals((byte) 0xFF, e[0]);
        assertArrayEquals(run, Cobs.decode(e, 0, e.length));
    }

    @Test
    void aHelloCarriesTheWholeLayout() {
        var layout = io.concord.agents.chair.ChairLayout.standard();
        BoardProtocol.Hello h = BoardProtocol.readHello(new Frame(Frame.Type.HELLO, 0, 0, 0, BoardProtocol.hello(7, "fw 1", layout)));
        assertEquals("fw 1", h.firmware());
        assertEquals(layout.sensors().size(), h.layout().sensors().size());
        for (int i = 0; i < layout.sensors().size(); i++) {
            assertEquals(layout.sensors().get(i).name(), h.layout().sensors().get(i).name());
            assertEquals(layout.sensors().get(i).direction(), h.layout().sensors().get(i).direction(), 0.001);
        }
        assertEquals(layout.metresPerTick(), h.layout().metresPerTick(), 1e-6);
    }
}
