package io.concord.jade;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;

/**
 * The body of a FIPA HTTP MTP request (SC00084): a {@code multipart/mixed} of two parts, the XML
 * envelope and the ACL payload, as JADE 4.3 writes and reads it. The one place for the format: the
 * client ({@link MtpClient}) encodes with it, the server ({@link HttpMtp}) decodes with it.
 *
 * <p>As JADE writes it: a line that is not part of the message, then each part's delimiter
 * {@code --boundary}, its {@code Content-Type} and a blank line, each line ended by CRLF, and the
 * closing delimiter {@code --boundary--}; the Content-Type header has a space before its
 * {@code ;} and the boundary in quotes. Read leniently: LF alone ends a line, the boundary may be
 * quoted or not, parts after the second are not read.
 */
final class MtpMultipart {
    private static final String PREAMBLE = "This is not part of the MIME multipart encoded message.";

    private MtpMultipart() {
    }

    /** A new random boundary, as JADE makes them: 31 hex digits. */
    static String newBoundary() {
        byte[] rnd = new byte[16];
        java.util.concurrent.ThreadLocalRandom.current().nextBytes(rnd);
        return HexFormat.of().formatHex(rnd).substring(1);
    }

    /** The request's Content-Type for a body with that boundary. */
    static String contentType(String boundary) {
        return "multipart/mixed ; boundary=\"" + boundary + "\"";
    }

    /** The body: the envelope's XML (in UTF-8), then the payload's bytes, as the string ACL in UTF-8. */
    static byte[] encode(String boundary, String envelopeXml, byte[] payload) {
        ByteArrayOutputStream body = new ByteArrayOutputStream(payload.length + 1024);
        body.writeBytes((PREAMBLE + "\r\n--" + boundary
                + "\r\nContent-Type: application/xml\r\n\r\n" + envelopeXml + "\r\n--" + boundary
                + "\r\nContent-Type: application/text; charset=UTF-8\r\n\r\n").getBytes(StandardCharsets.UTF_8));
        body.writeBytes(payload);
        body.writeBytes(("\r\n--" + boundary + "--\r\n").getBytes(StandardCharsets.UTF_8));
        return body.toByteArray();
    }

    /** The boundary a Content-Type names (quoted or not), or null if it is not {@code multipart/mixed} with one. */
    static String boundaryOf(String contentType) {
        if (contentType == null || !contentType.toLowerCase(Locale.ROOT).startsWith("multipart/mixed")) {
            return null;
        }
        int at = contentType.toLowerCase(Locale.ROOT).indexOf("boundary=");
        if (at < 0) {
            return null;
        }
        String b = contentType.substring(at + 9).trim();
        int semi = b.indexOf(';');
        if (b.startsWith("\"")) {
            int end = b.indexOf('"', 1);
            return end > 1 ? b.substring(1, end) : null;
        }
        b = semi >= 0 ? b.substring(0, semi).trim() : b;
        return b.isEmpty() ? null : b;
    }

    /**
     * A body's first two parts, the envelope and the payload, as ISO-8859-1 text (one char a byte,
     * so that their bytes survive: {@link #bytes}).
     */
    static final class Parts {
        private final String envelopePart;
        private final String payloadPart;

        private Parts(String envelopePart, String payloadPart) {
            this.envelopePart = envelopePart;
            this.payloadPart = payloadPart;
        }

        /**
         * The envelope's XML, after its part's headers and blank line.
         *
         * @throws IllegalArgumentException if the part has no blank line after its headers
         */
        String envelope() {
            return content(envelopePart);
        }

        /**
         * The payload, after its part's headers and blank line.
         *
         * @throws IllegalArgumentException if the part has no blank line after its headers
         */
        String payload() {
            return content(payloadPart);
        }
    }

    /** A part's content back to its bytes. */
    static byte[] bytes(String content) {
        return content.getBytes(StandardCharsets.ISO_8859_1);
    }

    /**
     * Reads a body (as ISO-8859-1 text, so bytes survive) into its first two parts.
     *
     * @throws IllegalArgumentException if the boundary never shows, a part is never closed, or
     *                                  there are fewer than two parts
     */
    static Parts decode(String body, String boundary) {
        List<String> parts = split(body, boundary);
        return new Parts(parts.get(0), parts.get(1));
    }

    /**
     * The first two parts of a body, headers and all (any further part is not read). Each
     * delimiter is found by one scan from where the last ended: the work is linear in the body's
     * length however many parts it has.
     *
     * @throws IllegalArgumentException if the boundary never shows or a part is never closed
     */
    static List<String> split(String body, String boundary) {
        String delim = "--" + boundary;
        String close = "\n" + delim;
        int at = 0;
        if (!body.startsWith(delim)) {
            at = body.indexOf(close) + 1;
            if (at == 0) {
                throw new IllegalArgumentException("the body never shows the boundary " + boundary);
            }
        }
        List<String> parts = new ArrayList<>(2);
        while (parts.size() < 2) {
            int start = at + delim.length();
            if (body.startsWith("--", start)) {
                break; // the closing delimiter
            }
            int end = body.indexOf(close, start);
            if (end < 0) {
                throw new IllegalArgumentException("a multipart part is never closed by --" + boundary);
            }
            parts.add(body.substring(start, end > start && body.charAt(end - 1) == '\r' ? end - 1 : end));
            at = end + 1;
        }
        if (parts.size() < 2) {
            throw new IllegalArgumentException("a FIPA message has two parts, the envelope and the payload; got " + parts.size());
        }
        return parts;
    }

    /** The content of a part: after its headers and the blank line. */
    private static String content(String part) {
        int crlf = part.indexOf("\r\n\r\n");
        int lf = part.indexOf("\n\n");
        int cut;
        int skip;
        if (crlf >= 0 && (lf < 0 || crlf <= lf)) {
            cut = crlf;
            skip = 4;
        } else if (lf >= 0) {
            cut = lf;
            skip = 2;
        } else {
            throw new IllegalArgumentException("a multipart part has no blank line after its headers");
        }
        return part.substring(cut + skip);
    }
}
