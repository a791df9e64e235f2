package io.concord.layers.authority;

import org.bouncycastle.crypto.params.Ed25519PublicKeyParameters;
import org.bouncycastle.crypto.signers.Ed25519Signer;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The operators a ward trusts, and the check of their signed orders: the signature under the
 * named operator's key, the order's action and target, its age (at most {@link #MAX_AGE_MS} old,
 * at most {@link #MAX_AHEAD_MS} ahead of this clock), and its nonce never seen before (remembered
 * for as long as the order could be fresh, at most {@link #MAX_REMEMBERED}). Not thread-safe: one
 * per agent, used on its loop.
 */
public final class Operators {
    /** How old an order may be when it arrives. */
    public static final long MAX_AGE_MS = 60_000;
    /** How far ahead of the verifier's clock an order may be stamped (clocks differ a little). */
    public static final long MAX_AHEAD_MS = 10_000;
    /** Nonces remembered at most; past it an order is refused until old ones age out. */
    public static final int MAX_REMEMBERED = 4_096;

    private final Map<String, Operator> byName = new LinkedHashMap<>();
    private final Map<String, Long> seen = new LinkedHashMap<>();

    private Operators(List<Operator> ops) {
        for (Operator o : ops) {
            byName.put(o.name(), o);
        }
    }

    /** These operators. */
    public static Operators of(Operator... ops) {
        return new Operators(List.of(ops));
    }

    /** These operators. */
    public static Operators of(List<Operator> ops) {
        return new Operators(ops);
    }

    /** No operator: every order is refused (a ward that configured none). */
    public static Operators none() {
        return new Operators(List.of());
    }

    /** The operators' names. */
    public List<String> names() {
        return List.copyOf(byName.keySet());
    }

    /** A copy with the same operators and no memory of nonces (a second agent of the ward). */
    public Operators copy() {
        return new Operators(new ArrayList<>(byName.values()));
    }

    /**
     * Reads the {@code operator <hex> <name>} lines of a file (an operators file, or an operator's
     * key file, of which only that line is read); {@code #} starts a comment.
     *
     * @throws IllegalArgumentException naming the file and line that is wrong
     */
    public static Operators read(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read the operators file " + file + ": " + e.getMessage(), e);
        }
        List<Operator> ops = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String t = lines.get(i).strip();
            if (t.isEmpty() || t.startsWith("#") || t.startsWith("private ")) {
                continue;
            }
            ops.add(parseLine(t, file + " line " + (i + 1)));
        }
        if (ops.isEmpty()) {
            throw new IllegalArgumentException(file + " names no operator (lines 'operator <64 hex digits> <name>')");
        }
        return new Operators(ops);
    }

    static Operator parseLine(String t, String where) {
        String[] f = t.split("\\s+", 3);
        if (f.length != 3 || !f[0].equals("operator")) {
            throw new IllegalArgumentException(where + ": expected 'operator <64 hex digits> <name>', got '"
                    + t.substring(0, Math.min(80, t.length())) + "'");
        }
        try {
            return new Operator(f[2].strip(), HexFormat.of().parseHex(f[1]));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(where + ": " + e.getMessage(), e);
        }
    }

    /**
     * Checks an order for {@code action} on {@code target} at {@code nowMs}: null if it is good (its
     * nonce is then remembered, so it is good once), else why not.
     */
    public String verify(SignedOrder o, String action, String target, long nowMs) {
        Operator op = byName.get(o.operator());
        if (op == null) {
            return o.operator() + " is not an operator of this ward" + (byName.isEmpty() ? " (it has none configured)"
                    : " (its operators: " + String.join(", ", byName.keySet()) + ")");
        }
        byte[] data = o.signedBytes();
        boolean good;
        try {
            Ed25519Signer s = new Ed25519Signer();
            s.init(false, new Ed25519PublicKeyParameters(op.publicKey(), 0));
            s.update(data, 0, data.length);
            good = s.verifySignature(o.signatureBytes());
        } catch (IllegalArgumentException e) {
            good = false;
        }
        if (!good) {
            return "the order's signature is not " + o.operator() + "'s (forged, or changed after it was signed)";
        }
        if (!o.action().equals(action) || !o.target().equalsIgnoreCase(target)) {
            return "the order is to " + o.action() + " " + o.target() + ", not to " + action + " " + target;
        }
        if (nowMs - o.atMs() > MAX_AGE_MS) {
            return "the order is " + (nowMs - o.atMs()) / 1000 + " s old; an order is good for " + MAX_AGE_MS / 1000 + " s";
        }
        if (o.atMs() - nowMs > MAX_AHEAD_MS) {
            return "the order is stamped " + (o.atMs() - nowMs) / 1000 + " s ahead of this clock";
        }
        for (Iterator<Map.Entry<String, Long>> it = seen.entrySet().iterator(); it.hasNext(); ) {
            if (nowMs - it.next().getValue() > MAX_AGE_MS + MAX_AHEAD_MS) {
                it.remove();
            } else {
                break;   // in order of arrival: the rest are younger
            }
        }
        String key = o.operator() + "|" + o.nonce();
        if (seen.containsKey(key)) {
            return "the order was given already (a replay): an order is good once";
        }
        if (seen.size() >= MAX_REMEMBERED) {
            return "more than " + MAX_REMEMBERED + " orders in " + (MAX_AGE_MS + MAX_AHEAD_MS) / 1000 + " s; try again later";
        }
        seen.put(key, nowMs);
        return null;
    }
}
