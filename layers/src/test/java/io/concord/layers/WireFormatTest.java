package io.concord.layers;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.SecurityLayer;
import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Checks the frame test vectors of docs/wire-format.md, read from the document itself. */
class WireFormatTest {

    private static List<Map<String, String>> vectors() throws Exception {
        Path doc = Path.of("..", "docs", "wire-format.md");
        List<Map<String, String>> out = new ArrayList<>();
        Map<String, String> current = null;
        for (String line : Files.readAllLines(doc)) {
            if (line.equals("```vector")) {
                current = new HashMap<>();
            } else if (line.equals("```") && current != null) {
                out.add(current);
                current = null;
            } else if (current != null) {
                int colon = line.indexOf(':');
                current.put(line.substring(0, colon).trim(), line.substring(colon + 1).trim());
            }
        }
        return out;
    }

    @Test
    void theDocumentedFramesAreWhatTheSecurityLayerWritesAndReads() throws Exception {
        List<Map<String, String>> vectors = vectors();
        assertEquals(3, vectors.size(), "three vectors in the document");
        HexFormat hex = HexFormat.of();
        for (Map<String, String> v : vectors) {
            SecurityLayer.Protection p = SecurityLayer.Protection.valueOf(v.get("protection"));
            byte[] body = hex.parseHex(v.get("body"));
            SecurityLayer writer = new SecurityLayer(new SecurityLayer.Config(p, Stacks.KEY, null, 30_000, 16));
            LayerHarness a = new LayerHarness("a@p", new ManualClock(), writer);
            writer.setNextCounter(1);
            byte[] buf = new byte[Frames.HEADROOM + body.length];
            System.arraycopy(body, 0, buf, Frames.HEADROOM, body.length);
            a.sendDown(Envelope.control(Frames.id("b@p"), new Address("h", 1), buf, Frames.HEADROOM, body.length));
            byte[] frame = a.pollDown().dataCopy();
            assertEquals(v.get("frame"), hex.formatHex(frame), p + ": the frame, byte for byte");

            LayerHarness b = new LayerHarness("b@p", new ManualClock(),
                    new SecurityLayer(new SecurityLayer.Config(p, Stacks.KEY, null, 30_000, 16)));
            b.receiveUp(Envelope.incoming(new Address("h", 2), frame, 0, frame.length, 0));
            Envelope opened = b.pollUp();
            assertTrue(opened != null, p + " opens");
            assertArrayEquals(body, opened.dataCopy(), p + ": the body");
            assertEquals(Frames.id("a@p"), opened.peerId());
        }
    }

    @Test
    void idsAreTheFirstBytesOfTheNamesHash() {
        assertEquals(0xc492b19e3054662eL, Frames.id("a@p"));
        assertEquals(Frames.id("A@P"), Frames.id("a@p"));
    }
}
