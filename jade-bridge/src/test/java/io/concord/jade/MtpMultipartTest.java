package io.concord.jade;

import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The HTTP MTP's multipart body: what the client writes, the server reads back, byte for byte. */
class MtpMultipartTest {
    private static final String ENVELOPE = "<?xml version=\"1.0\"?>\n<envelope><params index=\"1\"><from><agent-identifier>"
            + "<name>Zoë@Café</name></agent-identifier></from></params></envelope>";
    private static final byte[] PAYLOAD = "(INFORM :content \"prix: 42 €\r\n--not a delimiter\")".getBytes(StandardCharsets.UTF_8);

    @Test
    void whatItEncodesItDecodes() {
        String boundary = MtpMultipart.newBoundary();
        assertTrue(boundary.matches("[0-9a-f]{31}"), boundary);
        byte[] body = MtpMultipart.encode(boundary, ENVELOPE, PAYLOAD);
        assertEquals(boundary, MtpMultipart.boundaryOf(MtpMultipart.contentType(boundary)));
        MtpMultipart.Parts parts = MtpMultipart.decode(new String(body, StandardCharsets.ISO_8859_1), boundary);
        assertArrayEquals(ENVELOPE.getBytes(StandardCharsets.UTF_8), MtpMultipart.bytes(parts.envelope()));
        assertArrayEquals(PAYLOAD, MtpMultipart.bytes(parts.payload()));
    }

    @Test
    void itWritesTheBodyAndItsContentTypeAsJadeDoes() {
        assertEquals("multipart/mixed ; boundary=\"b0\"", MtpMultipart.contentType("b0"));
        assertEquals("This is not part of the MIME multipart encoded message.\r\n"
                        + "--b0\r\nContent-Type: application/xml\r\n\r\n<envelope/>\r\n"
                        + "--b0\r\nContent-Type: application/text; charset=UTF-8\r\n\r\n(INFORM)\r\n"
                        + "--b0--\r\n",
                new String(MtpMultipart.encode("b0", "<envelope/>", "(INFORM)".getBytes(StandardCharsets.UTF_8)), StandardCharsets.UTF_8));
    }

    @Test
    void itReadsTheBodyJadeWritesAndOneWithBareLineFeeds() {
        MtpMultipart.Parts jade = MtpMultipart.decode(WireTest.JADE_BODY, "7b446481f5ae2c17c233efb80dd6246");
        assertTrue(jade.envelope().startsWith("<?xml") && jade.envelope().endsWith("</envelope>"), jade.envelope());
        assertTrue(jade.payload().startsWith("(REQUEST") && jade.payload().endsWith(":content  \"ping\" )"), jade.payload());
        MtpMultipart.Parts lf = MtpMultipart.decode("--b\nContent-Type: application/xml\n\n<e/>\n--b\n\n(INFORM)\n--b--\n", "b");
        assertEquals("<e/>", lf.envelope());
        assertEquals("(INFORM)", lf.payload());
    }

    @Test
    void theBoundaryIsReadQuotedOrNotAndOnlyFromMultipartMixed() {
        assertEquals("abc", MtpMultipart.boundaryOf("multipart/mixed; boundary=abc; charset=x"));
        assertEquals("a b", MtpMultipart.boundaryOf("Multipart/Mixed ; boundary=\"a b\""));
        assertNull(MtpMultipart.boundaryOf("multipart/mixed"));
        assertNull(MtpMultipart.boundaryOf("multipart/mixed; boundary="));
        assertNull(MtpMultipart.boundaryOf("text/plain; boundary=abc"));
        assertNull(MtpMultipart.boundaryOf(null));
    }

    @Test
    void aBodyItCannotReadIsRefusedWithTheReason() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> MtpMultipart.decode("no delimiter", "b"))
                .getMessage().contains("never shows the boundary"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> MtpMultipart.decode("--b\n\n<e/>\n--b--\n", "b"))
                .getMessage().contains("two parts"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> MtpMultipart.decode("--b\n\n<e/>\n--b\n\n(x)", "b"))
                .getMessage().contains("never closed"));
        MtpMultipart.Parts headless = MtpMultipart.decode("--b\nno blank line\n--b\n\n(x)\n--b--", "b");
        assertTrue(assertThrows(IllegalArgumentException.class, headless::envelope).getMessage().contains("no blank line"));
    }
}
