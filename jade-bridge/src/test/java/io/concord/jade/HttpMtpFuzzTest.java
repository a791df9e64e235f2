package io.concord.jade;

import io.concord.core.acl.AID;
import org.junit.jupiter.api.Test;

import java.time.Duration;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What the HTTP MTP reads from the network, mutated at random from the request JADE sends: the
 * Content-Type header, the multipart body, the XML envelope and the string ACL message. Whatever
 * arrives is either read or refused with an {@link IllegalArgumentException} (a 400 with its
 * reason); nothing else escapes, and a message that comes out in the name of an agent of this
 * platform is always refused (nothing forged is delivered). {@code -Dconcord.fuzz} inputs
 * (100,000 by default, as in CI).
 */
class HttpMtpFuzzTest {
    private static final int INPUTS = Integer.getInteger("concord.fuzz", 100_000);
    private static final String BOUNDARY = "7b446481f5ae2c17c233efb80dd6246";
    private static final String[] PIECES = {"\r\n", "\r\n\r\n", "--", "--" + BOUNDARY, "--" + BOUNDARY + "--", "<", ">", "</",
            "<envelope>", "</envelope>", "<params index=\"2\">", "<agent-identifier>", "<name>", "</name>", "<url>",
            "&amp;", "&#0;", "&lt;", "&e;", "<![CDATA[", "]]>", "<!DOCTYPE x>", "<?xml version=\"1.0\"?>", "(", ")", "\"",
            "\\\"", "\\", ":sender", ":receiver", ":content", "(agent-identifier :name boss@foreignplat)",
            ":name boss@foreignplat", "(set", "(sequence", ":reply-by 20261123T000000000", ":reply-by 15000101T000000000Z",
            "#12\"", "99999999999", "-1", "\u00e9", "\u0000", "Content-Type: application/text", "x".repeat(500)};
    private static final String[] POSING = {"boss@foreignplat", "boss@FOREIGNPLAT", "\"boss@foreignplat\"",
            "boss@foreignplat :addresses (sequence http://127.0.0.1:1/acc)", "BOSS@ForeignPlat"};
    private static final String[] TYPES = {"multipart/mixed ; boundary=\"" + BOUNDARY + "\"", "multipart/mixed; boundary=" + BOUNDARY,
            "multipart/mixed", "text/plain", "multipart/mixed; boundary=\"\"", "multipart/mixed; boundary=\"a\"; boundary=b",
            "MULTIPART/MIXED;BOUNDARY=" + BOUNDARY, null};

    @Test
    void everyRequestIsReadOrRefusedWithAReasonAndNoneSpeaksForThisPlatform() {
        assertTimeoutPreemptively(Duration.ofMinutes(5), this::run, "an input hung the HTTP MTP's reader");
    }

    private void run() {
        SplittableRandom r = new SplittableRandom(11232026);
        int read = 0;
        int refused = 0;
        int posing = 0;
        for (int i = 0; i < INPUTS; i++) {
            String type = r.nextInt(10) < 7 ? TYPES[0] : TYPES[r.nextInt(TYPES.length)];
            if (type != null && r.nextInt(4) == 0) {
                type = mutate(type, r);
            }
            String seed = WireTest.JADE_BODY;
            if (r.nextInt(3) == 0) {
                // Someone posing as an agent of this platform, written every way the codec might read.
                seed = seed.replace(":name echo@TestPlat", ":name " + POSING[r.nextInt(POSING.length)]);
            }
            String body = mutate(seed, r);
            String boundary;
            HttpMtp.Inbound in;
            try {
                boundary = type == null ? null : MtpMultipart.boundaryOf(type);
                if (boundary == null) {
                    refused++;
                    continue;
                }
                in = HttpMtp.parse(body, boundary);
            } catch (IllegalArgumentException e) {
                assertTrue(e.getMessage() != null && !e.getMessage().isBlank(), "a refusal says why");
                refused++;
                continue;
            }
            read++;
            AID sender = in.message().getSender();
            assertTrue(sender != null, "a message read has a sender");
            if ("foreignplat".equalsIgnoreCase(sender.platform())) {
                posing++;
                final HttpMtp.Inbound posed = in;
                assertThrows(IllegalArgumentException.class, () -> HttpMtp.checkForeignSender(posed, "foreignplat"),
                        "a message in the name of an agent of this platform is refused: " + body);
            } else {
                HttpMtp.checkForeignSender(in, "foreignplat");
            }
        }
        System.out.println("fuzzed " + INPUTS + " HTTP requests: " + read + " read, " + refused + " refused with a reason, "
                + posing + " posing as an agent of this platform (all refused)");
        assertTrue(read > INPUTS / 20 && refused > INPUTS / 20 && posing > INPUTS / 100, "the inputs reach every outcome: " + read + " read, " + refused + " refused, " + posing + " posing");
    }

    private static String mutate(String seed, SplittableRandom r) {
        StringBuilder b = new StringBuilder(seed);
        int edits = 1 + r.nextInt(3);
        for (int e = 0; e < edits; e++) {
            int at = b.length() == 0 ? 0 : r.nextInt(b.length() + 1);
            switch (r.nextInt(6)) {
                case 0, 1 -> b.insert(at, PIECES[r.nextInt(PIECES.length)]);
                case 2 -> b.delete(at, Math.min(b.length(), at + r.nextInt(30)));
                case 3 -> {
                    if (at < b.length()) {
                        b.setCharAt(at, (char) r.nextInt(0x100));
                    }
                }
                case 4 -> b.insert(at, b.substring(at, Math.min(b.length(), at + r.nextInt(60))));
                default -> {
                    if (r.nextInt(4) == 0) {
                        b.setLength(Math.min(b.length(), at));
                    }
                }
            }
        }
        return b.toString();
    }
}
