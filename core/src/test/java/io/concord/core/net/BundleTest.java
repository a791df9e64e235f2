package io.concord.core.net;

import org.junit.jupiter.api.Test;

import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The frames one cycle of the loop sends to one address on one lane go out as one datagram at the
 * cycle's end (docs/wire-format.md, "Bundles"): real sockets on 127.0.0.1, a raw channel on the
 * other end to see the datagrams as they are.
 */
class BundleTest {
    private static final Receiver IGNORE = (from, data, offset, length, nowNs) -> { };

    /** A frame of {@code n} bytes, each {@code tag}. */
    private static byte[] frame(int tag, int n) {
        byte[] b = new byte[n];
        Arrays.fill(b, (byte) tag);
        return b;
    }

    /** The datagrams waiting at the raw channel. */
    private static List<byte[]> datagrams(DatagramChannel raw) throws Exception {
        List<byte[]> out = new ArrayList<>();
        ByteBuffer buf = ByteBuffer.allocate(SocketNetwork.MAX_DATAGRAM + 1);
        while (raw.receive(buf.clear()) != null) {
            out.add(Arrays.copyOf(buf.array(), buf.position()));
        }
        return out;
    }

    private static DatagramChannel raw() throws Exception {
        DatagramChannel raw = DatagramChannel.open();
        raw.bind(new InetSocketAddress("127.0.0.1", 0));
        raw.configureBlocking(false);
        return raw;
    }

    private static Address at(DatagramChannel raw) throws Exception {
        return new Address("127.0.0.1", ((InetSocketAddress) raw.getLocalAddress()).getPort());
    }

    /** The frames of a bundle, as the wire format says to read it. */
    private static List<byte[]> parts(byte[] d) {
        assertEquals(0xC0, d[0] & 0xFF);
        assertEquals(0x7B, d[1] & 0xFF);
        List<byte[]> out = new ArrayList<>();
        int at = 2;
        while (at < d.length) {
            int n = (d[at] & 0xFF) << 8 | d[at + 1] & 0xFF;
            out.add(Arrays.copyOfRange(d, at + 2, at + 2 + n));
            at += 2 + n;
        }
        return out;
    }

    @Test
    void framesOfOneCycleToOneAddressLeaveAsOneDatagramInOrder() throws Exception {
        try (SocketNetwork net = new SocketNetwork(1 << 20, false); DatagramChannel raw = raw()) {
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            for (int i = 1; i <= 10; i++) {
                assertTrue(a.send(at(raw), frame(i, 100), 0, 100, 0));
            }
            assertTrue(datagrams(raw).isEmpty(), "nothing leaves before the cycle ends");
            net.flush();
            List<byte[]> got = datagrams(raw);
            assertEquals(1, got.size(), "one datagram");
            List<byte[]> parts = parts(got.get(0));
            assertEquals(10, parts.size());
            for (int i = 1; i <= 10; i++) {
                assertArrayEquals(frame(i, 100), parts.get(i - 1));
            }
        }
    }

    @Test
    void aLoneFrameLeavesAsItIsAndCopiesOnOtherLanesNeverShareADatagram() throws Exception {
        try (SocketNetwork net = new SocketNetwork(1 << 20, false); DatagramChannel raw = raw()) {
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            a.send(at(raw), frame(7, 50), 0, 50, 0);
            net.flush();
            List<byte[]> got = datagrams(raw);
            assertEquals(1, got.size());
            assertArrayEquals(frame(7, 50), got.get(0), "no bundle around a single frame");
            for (int i = 1; i <= 3; i++) {
                a.send(at(raw), frame(i, 60), 0, 60, 0);
                a.send(at(raw), frame(i, 60), 0, 60, 1); // its copy
            }
            net.flush();
            got = datagrams(raw);
            assertEquals(2, got.size(), "one datagram per lane");
            for (byte[] d : got) {
                List<byte[]> parts = parts(d);
                assertEquals(3, parts.size());
                assertEquals(3, parts.stream().map(p -> p[0]).distinct().count(), "no frame twice in one datagram");
            }
        }
    }

    @Test
    void aBundleStaysWithinItsLimitAndAFrameTooLargeForOneLeavesAloneAfterWhatWasGathered() throws Exception {
        try (SocketNetwork net = new SocketNetwork(1 << 20, false); DatagramChannel raw = raw()) {
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            int n = 1_000;
            int frames = 3 * SocketNetwork.LOOPBACK_BUNDLE_BYTES / n;
            for (int i = 0; i < frames; i++) {
                a.send(at(raw), frame(i, n), 0, n, 0);
            }
            a.send(at(raw), frame(99, 20_000), 0, 20_000, 0);
            a.send(at(raw), frame(100, 10), 0, 10, 0);
            net.flush();
            List<byte[]> got = datagrams(raw);
            List<byte[]> inOrder = new ArrayList<>();
            for (byte[] d : got) {
                assertTrue(d.length <= SocketNetwork.LOOPBACK_BUNDLE_BYTES || d.length == 20_000, "a datagram of " + d.length);
                if ((d[0] & 0xFF) == 0xC0 && (d[1] & 0xFF) == 0x7B) {
                    inOrder.addAll(parts(d));
                } else {
                    inOrder.add(d);
                }
            }
            assertEquals(frames + 2, inOrder.size());
            for (int i = 0; i < frames; i++) {
                assertEquals((byte) i, inOrder.get(i)[0], "frame " + i + " in its place");
            }
            assertEquals(20_000, inOrder.get(frames).length);
            assertEquals(10, inOrder.get(frames + 1).length);
            assertTrue(got.size() >= 4, "several bundles: " + got.size());
        }
    }

    @Test
    void aReceiverHandsUpEachFrameOfABundleAndWhatIsMalformedAsOnePieceForTheStackToDrop() throws Exception {
        List<byte[]> up = new ArrayList<>();
        try (SocketNetwork net = new SocketNetwork(1 << 20, false); DatagramChannel raw = raw()) {
            Endpoint b = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> up.add(Arrays.copyOfRange(data, offset, offset + length)));
            InetSocketAddress to = new InetSocketAddress("127.0.0.1", b.localAddress().port());
            // Two good frames, then a length that runs past the datagram.
            ByteBuffer d = ByteBuffer.allocate(64);
            d.put((byte) 0xC0).put((byte) 0x7B).putShort((short) 3).put(frame(1, 3)).putShort((short) 2).put(frame(2, 2))
                    .putShort((short) 40).put(frame(3, 5));
            raw.send(d.flip(), to);
            // More frames than a bundle may hold.
            ByteBuffer many = ByteBuffer.allocate(2 + 3 * (SocketNetwork.MAX_BUNDLE_FRAMES + 5));
            many.put((byte) 0xC0).put((byte) 0x7B);
            for (int i = 0; i < SocketNetwork.MAX_BUNDLE_FRAMES + 5; i++) {
                many.putShort((short) 1).put((byte) 4);
            }
            raw.send(many.flip(), to);
            net.poll(0);
            assertEquals(3 + SocketNetwork.MAX_BUNDLE_FRAMES + 1, up.size());
            assertArrayEquals(frame(1, 3), up.get(0));
            assertArrayEquals(frame(2, 2), up.get(1));
            assertEquals(7, up.get(2).length, "the rest, length and all, as one piece");
            assertEquals(15, up.get(3 + SocketNetwork.MAX_BUNDLE_FRAMES).length, "past the limit: the rest as one piece");
        }
    }

    /** The read budget counts frames, not datagrams: a flood of full bundles is read a bounded number of frames a poll. */
    @Test
    void aFloodOfBundlesOnOnePortIsReadABoundedNumberOfFramesAPoll() throws Exception {
        int[] flooded = new int[1];
        int[] quiet = new int[1];
        try (SocketNetwork net = new SocketNetwork(1 << 20, false); DatagramChannel raw = raw()) {
            Endpoint target = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> flooded[0]++);
            Endpoint other = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> quiet[0]++);
            ByteBuffer full = ByteBuffer.allocate(2 + 3 * SocketNetwork.MAX_BUNDLE_FRAMES);
            full.put((byte) 0xC0).put((byte) 0x7B);
            for (int i = 0; i < SocketNetwork.MAX_BUNDLE_FRAMES; i++) {
                full.putShort((short) 1).put((byte) 4);
            }
            full.flip();
            for (int i = 0; i < 20; i++) {
                raw.send(full.duplicate(), new InetSocketAddress("127.0.0.1", target.localAddress().port()));
            }
            raw.send(ByteBuffer.wrap(new byte[8]), new InetSocketAddress("127.0.0.1", other.localAddress().port()));
            net.poll(0);
            assertTrue(flooded[0] < SocketNetwork.READ_BUDGET + SocketNetwork.MAX_BUNDLE_FRAMES,
                    "one poll read " + flooded[0] + " frames from the flooded port");
            assertEquals(1, quiet[0], "and the other port in the same poll");
            while (flooded[0] < 20 * SocketNetwork.MAX_BUNDLE_FRAMES) {
                assertTrue(net.poll(0) > 0, "the rest over the next polls, none lost");
            }
        }
    }

    /** The example of docs/wire-format.md, "Bundles". */
    @Test
    void theWireFormatsExampleIsReadAsItsTwoFrames() throws Exception {
        List<byte[]> up = new ArrayList<>();
        try (SocketNetwork net = new SocketNetwork(1 << 20, false); DatagramChannel raw = raw()) {
            Endpoint b = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> up.add(Arrays.copyOfRange(data, offset, offset + length)));
            raw.send(ByteBuffer.wrap(java.util.HexFormat.of().parseHex("c07b0003aabbcc0002ddee")),
                    new InetSocketAddress("127.0.0.1", b.localAddress().port()));
            net.poll(0);
            assertEquals(2, up.size());
            assertArrayEquals(java.util.HexFormat.of().parseHex("aabbcc"), up.get(0));
            assertArrayEquals(java.util.HexFormat.of().parseHex("ddee"), up.get(1));
        }
    }

    @Test
    void withBundlingOffEachFrameIsADatagram() throws Exception {
        try (SocketNetwork net = new SocketNetwork(1 << 20, false, false); DatagramChannel raw = raw()) {
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            for (int i = 1; i <= 5; i++) {
                a.send(at(raw), frame(i, 100), 0, 100, 0);
            }
            net.flush();
            assertEquals(5, datagrams(raw).size());
        }
    }
}
