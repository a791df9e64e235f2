package io.concord.layers.authority;

import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.regex.Pattern;

/**
 * An operator's order, signed with the operator's key ({@link OperatorKey#sign}): what to do
 * ({@code resume}), to what ({@code chair1}), by whom, when (the signer's epoch milliseconds) and a
 * fresh nonce, so that it is good once, for that one target, for a short time. Written as one line
 * of text ({@link #encode()}), which travels in a message slot ({@code resume-request :order "..."}).
 *
 * <pre>concord-order-1|resume|chair1|nurse Ada|1700000000000|&lt;nonce, 16 bytes base64url&gt;|&lt;Ed25519 signature, base64url&gt;</pre>
 *
 * The signature covers everything before it, the version included (docs/security.md, "Operators").
 */
public record SignedOrder(String action, String target, String operator, long atMs, String nonce, String signature) {
    /** The version word that starts every order. */
    public static final String VERSION = "concord-order-1";
    /** Action, target and operator: letters, digits, spaces and {@code . _ - @ :}, 1 to 64 characters. */
    static final Pattern WORD = Pattern.compile("[\\p{L}\\p{N} ._@:-]{1,64}");
    private static final Pattern B64 = Pattern.compile("[A-Za-z0-9_-]{1,128}");

    public SignedOrder {
        check("action", action, WORD);
        check("target", target, WORD);
        check("operator", operator, WORD);
        check("nonce", nonce, B64);
        check("signature", signature, B64);
    }

    private static void check(String what, String v, Pattern p) {
        if (v == null || !p.matcher(v).matches()) {
            throw new IllegalArgumentException("an order's " + what + " must be " + (p == WORD
                    ? "1 to 64 letters, digits, spaces or . _ - @ :" : "base64url") + ", got " + (v == null ? "none"
                    : "'" + v.substring(0, Math.min(v.length(), 80)) + "'"));
        }
    }

    /** The bytes the signature covers. */
    static byte[] signed(String action, String target, String operator, long atMs, String nonce) {
        return (VERSION + "|" + action + "|" + target + "|" + operator + "|" + atMs + "|" + nonce).getBytes(StandardCharsets.UTF_8);
    }

    /** The bytes this order's signature covers. */
    byte[] signedBytes() {
        return signed(action, target, operator, atMs, nonce);
    }

    /** The signature's bytes (not checked here: {@link Operators#verify} does). */
    byte[] signatureBytes() {
        return Base64.getUrlDecoder().decode(signature);
    }

    /** The order as one line of text. */
    public String encode() {
        return VERSION + "|" + action + "|" + target + "|" + operator + "|" + atMs + "|" + nonce + "|" + signature;
    }

    /**
     * Reads an order written by {@link #encode()}.
     *
     * @throws IllegalArgumentException saying what is wrong with the text
     */
    public static SignedOrder parse(String text) {
        if (text == null || text.length() > 512) {
            throw new IllegalArgumentException(text == null ? "no order" : "an order is at most 512 characters, got " + text.length());
        }
        String[] f = text.trim().split("\\|", -1);
        if (f.length != 7 || !f[0].equals(VERSION)) {
            throw new IllegalArgumentException("an order is written " + VERSION + "|action|target|operator|epoch-ms|nonce|signature, got '"
                    + text.substring(0, Math.min(text.length(), 80)) + "'");
        }
        long at;
        try {
            at = Long.parseLong(f[4]);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("an order's time must be epoch milliseconds, got '" + f[4] + "'");
        }
        return new SignedOrder(f[1], f[2], f[3], at, f[5], f[6]);
    }

    @Override
    public String toString() {
        return action + " " + target + " by " + operator;
    }
}
