package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.layers.frame.Frames;

import javax.crypto.AEADBadTagException;
import javax.crypto.Cipher;
import java.security.GeneralSecurityException;
import javax.crypto.Mac;
import javax.crypto.spec.GCMParameterSpec;
import javax.crypto.spec.SecretKeySpec;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.zip.CRC32C;

/**
 * The security layer: frames every message with the Concord header (source and destination ids,
 * a counter), a CRC-32C safety code over header and body, and, by protection level, an HMAC or
 * AES-GCM tag that covers the header too. Under {@link Protection#GCM_PAIR} (class 7) data frames
 * use a key per pair of agents, agreed by X25519 in a handshake that each side signs with its
 * Ed25519 identity; identities are pinned on first use, so a member cannot later speak as another.
 *
 * <p>Receiving, it drops and counts: frames that are not Concord frames ({@code malformed-frame}),
 * frames for another agent ({@code misdirected}), frames with weaker protection than required
 * ({@code unprotected}), copies of a frame already accepted ({@code copy}), bad tags
 * ({@code bad-tag}), bad safety codes ({@code corrupt}), and handshakes that are stale, badly
 * signed or present another identity for a pinned name ({@code masquerade}).
 */
public final class SecurityLayer extends Layer {

    /** How frames are protected. */
    public enum Protection {
        /** CRC-32C only: closed networks. */
        CRC(Frames.PROTECTION_CRC),
        /** CRC-32C and HMAC-SHA256 (128-bit tag) with the platform key: class 3. */
        HMAC(Frames.PROTECTION_HMAC),
        /** CRC-32C inside AES-GCM with the platform key. */
        GCM_PLATFORM(Frames.PROTECTION_GCM_PLATFORM),
        /** CRC-32C inside AES-GCM with per-pair keys from a signed X25519 handshake: class 7. */
        GCM_PAIR(Frames.PROTECTION_GCM_PAIR);

        final int bits;

        Protection(int bits) {
            this.bits = bits;
        }
    }

    /**
     * @param protection       how data frames are protected
     * @param platformKey      the platform key (unused by {@link Protection#CRC})
     * @param identities       where the agent's identity comes from ({@link Protection#GCM_PAIR})
     * @param handshakeWindowMs how old a handshake may be
     * @param maxQueuedPerPeer messages held per peer while its handshake runs
     */
    public record Config(Protection protection, PlatformKey platformKey, IdentityStore identities,
                         long handshakeWindowMs, int maxQueuedPerPeer) {
        public Config {
            if (protection != Protection.CRC && platformKey == null) {
                throw new IllegalArgumentException(protection + " needs a platform key");
            }
            if (protection == Protection.GCM_PAIR && identities == null) {
                throw new IllegalArgumentException("GCM_PAIR needs an identity store");
            }
            if (handshakeWindowMs <= 0 || maxQueuedPerPeer < 1) {
                throw new IllegalArgumentException("handshakeWindowMs and maxQueuedPerPeer must be positive");
            }
        }
    }

    private static final int HELLO = 1;
    private static final int HELLO_REPLY = 2;
    /**
     * A notice, sealed with the platform key and not signed: "I hold no session key with you;
     * start a handshake". What a receiver sends, at most once a second per source, for a frame
     * sealed with a pair key it does not have (it restarted, or the frame is forged).
     */
    private static final int REKEY = 3;
    private static final long REKEY_EVERY_MS = 1_000;
    private static final int REKEY_MEMORY = 1024;
    private static final int RECENT_TAGS = 64;
    private static final int MAX_PAIRS = 4096;
    private static final long FIRST_RETRY_MS = 100;
    private static final int MAX_HELLO_ATTEMPTS = 10;

    private final Config config;
    private final CRC32C crc = new CRC32C();
    private final long[] recentTags = new long[RECENT_TAGS];
    private final byte[] nonce = new byte[12];
    private final Map<String, byte[]> pins = new HashMap<>();
    /**
     * Pairs, least recently used first. Only this agent's own sends and signed handshakes create
     * one, so strangers cannot push real pairs out; one pushed out by this agent's own traffic
     * to more than {@link #MAX_PAIRS} peers has its waiting messages counted as dropped.
     */
    private final Map<Long, Pair> pairs = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Pair> eldest) {
            if (size() > MAX_PAIRS) {
                evicted.add(eldest.getValue());
                return true;
            }
            return false;
        }
    };
    private final java.util.List<Pair> evicted = new java.util.ArrayList<>();
    /** When a REKEY notice last went to each source id (bounded: forgetting one costs a notice). */
    private final Map<Long, Long> rekeyed = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Long> eldest) {
            return size() > REKEY_MEMORY;
        }
    };
    private long rekeysSent;
    private long hellosSent;
    private int recentIndex;
    private long ownId;
    private String ownName;
    private long counter;
    private byte[] platformKeyBytes;
    private SecretKeySpec platformAead;
    private Cipher platformEncrypt;
    private Cipher platformDecrypt;
    private Mac mac;
    private Identity identity;

    /** What a layer keeps per peer under GCM_PAIR. */
    private static final class Pair {
        SecretKeySpec key;
        // One cipher per key and direction: the JDK expands an AES key again whenever a cipher is
        // initialised with another key than last time, which would cost more than the encryption.
        Cipher encrypt;
        Cipher decrypt;
        byte[] peerAgreement;
        Address address;
        final ArrayDeque<Envelope> queue = new ArrayDeque<>();
        long timer = -1;
        int attempts;
    }

    public SecurityLayer(Config config) {
        this.config = config;
    }

    @Override
    public String name() {
        return "security";
    }

    @Override
    public void init(LayerContext ctx) {
        ownName = ctx.host().nodeName();
        ownId = Frames.id(ownName);
        counter = new java.security.SecureRandom().nextLong() & 0x3FFF_FFFF_FFFF_FFFFL;
        try {
            if (config.protection() != Protection.CRC) {
                platformKeyBytes = config.platformKey().bytes();
                platformAead = new SecretKeySpec(Crypto.hkdf(platformKeyBytes, null, "concord platform aead v1", 16), "AES");
                platformEncrypt = Cipher.getInstance("AES/GCM/NoPadding");
                platformDecrypt = Cipher.getInstance("AES/GCM/NoPadding");
            }
            if (config.protection() == Protection.HMAC) {
                mac = Mac.getInstance("HmacSHA256");
                mac.init(new SecretKeySpec(Crypto.hkdf(platformKeyBytes, null, "concord platform mac v1", 32), "HmacSHA256"));
            }
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM lacks AES-GCM or HMAC-SHA256: " + e.getMessage(), e);
        }
        if (config.protection() == Protection.GCM_PAIR) {
            identity = config.identities().identityFor(ownName);
        }
    }

    /**
     * Sets the counter of the next frame. Frames start from a random counter; only test vectors
     * need a known one. Never reuse a counter under one key.
     */
    public void setNextCounter(long next) {
        counter = next;
    }

    /** This agent's identity (class 7), to sign membership changes with; {@code null} otherwise. */
    public Identity identity() {
        return identity;
    }

    /** Where the platform key came from (a file's path, "given in code"); never the key. */
    public String platformKeyOrigin() {
        return config.platformKey() == null ? "none" : config.platformKey().origin();
    }

    /** True once a session key with the peer exists (class 7). */
    public boolean hasSessionWith(long peerId) {
        Pair p = pairs.get(peerId);
        return p != null && p.key != null;
    }

    // ---- down ---------------------------------------------------------------------------------------

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        if (env.peerId() == Frames.ANY) {
            // For whoever holds the port: no pair key can exist yet; the platform key seals it.
            Protection p = config.protection() == Protection.GCM_PAIR ? Protection.GCM_PLATFORM : config.protection();
            seal(env, p.bits, 0, platformAead, platformEncrypt);
            ctx.passDown(env);
            return;
        }
        switch (config.protection()) {
            case CRC, HMAC, GCM_PLATFORM -> {
                seal(env, config.protection().bits, 0, platformAead, platformEncrypt);
                ctx.passDown(env);
            }
            case GCM_PAIR -> {
                Pair p = pairs.computeIfAbsent(env.peerId(), k -> new Pair());
                dropEvicted(ctx);
                if (p.key != null) {
                    seal(env, Frames.PROTECTION_GCM_PAIR, 0, p.key, p.encrypt);
                    ctx.passDown(env);
                    return;
                }
                if (p.queue.size() >= config.maxQueuedPerPeer()) {
                    ctx.drop(env, "handshake-queue-full", p.queue.size() + " messages already wait for the handshake");
                    return;
                }
                p.queue.add(env);
                p.address = env.destination();
                startHandshake(ctx, env.peerId(), p);
            }
        }
    }

    /** Counts the messages of pairs pushed out of the table: nothing is lost uncounted. */
    private void dropEvicted(LayerContext ctx) {
        for (Pair gone : evicted) {
            if (gone.timer >= 0) {
                ctx.host().cancel(gone.timer);
            }
            for (Envelope e : gone.queue) {
                ctx.drop(e, "pair-evicted", "more than " + MAX_PAIRS + " peers: the least recently used pair was forgotten");
            }
            gone.queue.clear();
        }
        evicted.clear();
    }

    private void seal(Envelope env, int protection, int flags, SecretKeySpec key, Cipher gcm) {
        int h = env.prepend(Frames.HEADER_BYTES);
        byte[] d = env.data();
        Frames.putShort(d, h, Frames.MAGIC);
        d[h + 2] = (byte) Frames.VERSION;
        d[h + 3] = (byte) (protection | flags);
        Frames.putLong(d, h + 4, ownId);
        Frames.putLong(d, h + 12, env.peerId());
        long ctr = counter++;
        Frames.putLong(d, h + 20, ctr);
        crc.reset();
        crc.update(d, h, env.length());
        int code = (int) crc.getValue();
        int at = env.append(Frames.CRC_BYTES);
        d = env.data();
        h = env.offset();
        Frames.putInt(d, at, code);
        if (protection == Frames.PROTECTION_HMAC) {
            mac.update(d, h, env.length());
            byte[] tag = mac.doFinal();
            int t = env.append(Frames.TAG_BYTES);
            System.arraycopy(tag, 0, env.data(), t, Frames.TAG_BYTES);
        } else if (protection >= Frames.PROTECTION_GCM_PLATFORM) {
            try {
                nonceFor(ownId, ctr);
                gcm.init(Cipher.ENCRYPT_MODE, key, new GCMParameterSpec(128, nonce));
                gcm.updateAAD(d, h, Frames.HEADER_BYTES);
                int bodyLen = env.length() - Frames.HEADER_BYTES;
                byte[] out = new byte[Frames.HEADER_BYTES + bodyLen + Frames.TAG_BYTES];
                System.arraycopy(d, h, out, 0, Frames.HEADER_BYTES);
                gcm.doFinal(d, h + Frames.HEADER_BYTES, bodyLen, out, Frames.HEADER_BYTES);
                env.setData(out, 0, out.length);
            } catch (GeneralSecurityException e) {
                throw new IllegalStateException("AES-GCM failed to encrypt: " + e.getMessage(), e);
            }
        }
    }

    /** Nonce: the sender's id prefix and its frame counter, unique per key as long as ids differ. */
    private void nonceFor(long senderId, long ctr) {
        Frames.putInt(nonce, 0, (int) (senderId >>> 32));
        Frames.putLong(nonce, 4, ctr);
    }

    // ---- up -----------------------------------------------------------------------------------------

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        int len = env.length();
        byte[] d = env.data();
        int h = env.offset();
        if (len < Frames.HEADER_BYTES + Frames.CRC_BYTES) {
            ctx.drop(env, "malformed-frame", len + " bytes, shorter than a frame header and safety code");
            return;
        }
        if (Frames.getShort(d, h) != Frames.MAGIC || d[h + 2] != Frames.VERSION) {
            ctx.drop(env, "malformed-frame", String.format("not a Concord v1 frame (starts %02x%02x%02x)",
                    d[h], d[h + 1], d[h + 2]));
            return;
        }
        int flags = d[h + 3] & 0xFF;
        if ((flags & ~(Frames.PROTECTION_MASK | Frames.FLAG_HANDSHAKE)) != 0) {
            ctx.drop(env, "malformed-frame", "unknown flags " + Integer.toHexString(flags));
            return;
        }
        int protection = flags & Frames.PROTECTION_MASK;
        boolean handshake = (flags & Frames.FLAG_HANDSHAKE) != 0;
        long src = Frames.getLong(d, h + 4);
        long dst = Frames.getLong(d, h + 12);
        long ctr = Frames.getLong(d, h + 20);
        boolean any = dst == Frames.ANY;
        if (dst != ownId && !any) {
            ctx.drop(env, "misdirected", "the frame is for agent id " + Long.toHexString(dst) + ", not for this one");
            return;
        }
        if (any && handshake) {
            ctx.drop(env, "malformed-frame", "a handshake addressed to any agent");
            return;
        }
        if (handshake && config.protection() != Protection.GCM_PAIR) {
            ctx.drop(env, "unprotected", "a handshake, but this agent does not use per-pair keys");
            return;
        }
        int required = handshake || (any && config.protection() == Protection.GCM_PAIR)
                ? Frames.PROTECTION_GCM_PLATFORM : config.protection().bits;
        if (protection != required) {
            ctx.drop(env, "unprotected", "protection " + protection + " where " + required + " is required");
            return;
        }
        byte[] body;
        int bodyOff;
        int bodyLen;
        long tagKey = 0;
        if (protection == Frames.PROTECTION_CRC) {
            body = d;
            bodyOff = h + Frames.HEADER_BYTES;
            bodyLen = len - Frames.HEADER_BYTES - Frames.CRC_BYTES;
        } else {
            if (len < Frames.HEADER_BYTES + Frames.CRC_BYTES + Frames.TAG_BYTES) {
                ctx.drop(env, "malformed-frame", len + " bytes, too short for an authenticated frame");
                return;
            }
            tagKey = Frames.getLong(d, h + len - Frames.TAG_BYTES);
            if (seenTag(tagKey)) {
                ctx.drop(env, "copy", "a copy of a frame already accepted");
                return;
            }
            if (protection == Frames.PROTECTION_HMAC) {
                mac.update(d, h, len - Frames.TAG_BYTES);
                byte[] expected = mac.doFinal();
                if (!MessageDigest.isEqual(Arrays.copyOf(expected, Frames.TAG_BYTES),
                        Arrays.copyOfRange(d, h + len - Frames.TAG_BYTES, h + len))) {
                    ctx.drop(env, "bad-tag", "HMAC mismatch from " + env.source() + ": forged, corrupted, or another platform key");
                    return;
                }
                body = d;
                bodyOff = h + Frames.HEADER_BYTES;
                bodyLen = len - Frames.HEADER_BYTES - Frames.CRC_BYTES - Frames.TAG_BYTES;
            } else {
                SecretKeySpec key = platformAead;
                Cipher gcm = platformDecrypt;
                if (protection == Frames.PROTECTION_GCM_PAIR) {
                    Pair p = pairs.get(src);
                    if (p == null || p.key == null) {
                        // Nothing here is authenticated yet: no state, no signature, and at most one
                        // small notice back a second per source id (the sender, if real, then starts
                        // the handshake, which costs it a signature first).
                        ctx.drop(env, "no-session-key", "no session key with " + Long.toHexString(src)
                                + " (this agent restarted, or the frame is forged); asks the sender for a handshake");
                        long now = ctx.host().clock().epochMillis();
                        Long last = rekeyed.get(src);
                        if (last == null || now - last >= REKEY_EVERY_MS) {
                            rekeyed.put(src, now);
                            sendRekey(ctx, src, env.source());
                        }
                        return;
                    }
                    key = p.key;
                    gcm = p.decrypt;
                }
                try {
                    nonceFor(src, ctr);
                    gcm.init(Cipher.DECRYPT_MODE, key, new GCMParameterSpec(128, nonce));
                    gcm.updateAAD(d, h, Frames.HEADER_BYTES);
                    body = gcm.doFinal(d, h + Frames.HEADER_BYTES, len - Frames.HEADER_BYTES);
                } catch (AEADBadTagException e) {
                    ctx.drop(env, "bad-tag", "AES-GCM tag mismatch from " + env.source()
                            + ": forged, corrupted, replayed under an old key, or another platform key");
                    return;
                } catch (GeneralSecurityException e) {
                    ctx.drop(env, "bad-tag", "AES-GCM refused the frame: " + e.getMessage());
                    return;
                }
                bodyOff = 0;
                bodyLen = body.length - Frames.CRC_BYTES;
            }
        }
        crc.reset();
        crc.update(d, h, Frames.HEADER_BYTES);
        crc.update(body, bodyOff, bodyLen);
        if ((int) crc.getValue() != Frames.getInt(body, bodyOff + bodyLen)) {
            ctx.drop(env, "corrupt", "the safety code does not match: the frame was damaged");
            return;
        }
        if (tagKey != 0) {
            rememberTag(tagKey);
        }
        if (handshake) {
            onHello(ctx, env, src, body, bodyOff, bodyLen);
            return;
        }
        env.setPeerId(src);
        env.setData(body, bodyOff, bodyLen);
        if (any) {
            env.putHeader(Frames.ENVELOPE_ANY, Boolean.TRUE);
        }
        ctx.passUp(env);
    }

    private boolean seenTag(long tag) {
        for (long t : recentTags) {
            if (t == tag) {
                return true;
            }
        }
        return false;
    }

    private void rememberTag(long tag) {
        recentTags[recentIndex] = tag;
        recentIndex = (recentIndex + 1) % RECENT_TAGS;
    }

    // ---- handshake ------------------------------------------------------------------------------

    /** Sends a hello and keeps repeating it until answered, unless a handshake is already running. */
    private void startHandshake(LayerContext ctx, long peerId, Pair p) {
        if (p.timer < 0) {
            p.attempts = 0;
            sendHello(ctx, peerId, p.address, HELLO);
            scheduleRetry(ctx, peerId, p);
        }
    }

    /** Asks a peer for a handshake: one byte of body, sealed with the platform key. */
    private void sendRekey(LayerContext ctx, long peerId, Address to) {
        byte[] buf = new byte[Frames.HEADROOM + 1 + 40];
        buf[Frames.HEADROOM] = (byte) REKEY;
        Envelope env = Envelope.control(peerId, to, buf, Frames.HEADROOM, 1);
        seal(env, Frames.PROTECTION_GCM_PLATFORM, Frames.FLAG_HANDSHAKE, platformAead, platformEncrypt);
        rekeysSent++;
        ctx.passDown(env);
    }

    /** A peer holds no session key with this agent: forget ours and agree a new one (our frames wait meanwhile). */
    private void onRekey(LayerContext ctx, Envelope env, long src, int len) {
        if (len != 1) {
            ctx.drop(env, "malformed-handshake", "a rekey notice of " + len + " bytes");
            return;
        }
        Pair p = pairs.get(src);
        if (p == null) {
            // Nothing was sent to it: nothing to recover. Its next message will find a handshake.
            ctx.drop(env, "no-session-key", "a rekey notice from " + Long.toHexString(src) + ", which this agent has no pair with");
            return;
        }
        p.key = null;
        p.peerAgreement = null;
        p.address = env.source();
        startHandshake(ctx, src, p);
    }

    /** REKEY notices sent (tests, the console). */
    public long rekeysSent() {
        return rekeysSent;
    }

    /** Signed HELLOs and replies sent (tests, the console). */
    public long hellosSent() {
        return hellosSent;
    }

    /** Pairs held. */
    public int pairCount() {
        return pairs.size();
    }

    private void sendHello(LayerContext ctx, long peerId, Address to, int type) {
        hellosSent++;
        byte[] name = ownName.getBytes(StandardCharsets.UTF_8);
        int signedLen = 1 + 2 + name.length + 32 + 32 + 8;
        byte[] buf = new byte[Frames.HEADROOM + signedLen + 8 + 64 + 40];
        int o = Frames.HEADROOM;
        buf[o] = (byte) type;
        Frames.putShort(buf, o + 1, name.length);
        System.arraycopy(name, 0, buf, o + 3, name.length);
        int p = o + 3 + name.length;
        System.arraycopy(identity.signingPublicKey(), 0, buf, p, 32);
        System.arraycopy(identity.agreementPublicKey(), 0, buf, p + 32, 32);
        Frames.putLong(buf, p + 64, ctx.host().clock().epochMillis());
        // The signature also covers the destination id, so a hello cannot be replayed to another agent.
        Frames.putLong(buf, o + signedLen, peerId);
        byte[] sig = identity.sign(buf, o, signedLen + 8);
        System.arraycopy(sig, 0, buf, o + signedLen, 64);
        Envelope env = Envelope.control(peerId, to, buf, o, signedLen + 64);
        seal(env, Frames.PROTECTION_GCM_PLATFORM, Frames.FLAG_HANDSHAKE, platformAead, platformEncrypt);
        ctx.passDown(env);
    }

    private void scheduleRetry(LayerContext ctx, long peerId, Pair p) {
        long delayMs = Math.min(2_000, FIRST_RETRY_MS << Math.min(p.attempts, 5));
        p.timer = ctx.host().schedule(ctx.nowNs() + delayMs * 1_000_000L, () -> {
            p.timer = -1;
            if (p.key != null) {
                return;
            }
            if (++p.attempts >= MAX_HELLO_ATTEMPTS) {
                for (Envelope e : p.queue) {
                    ctx.drop(e, "no-handshake", "peer " + Long.toHexString(peerId) + " at " + p.address
                            + " did not answer " + MAX_HELLO_ATTEMPTS + " handshakes");
                }
                p.queue.clear();
                return;
            }
            sendHello(ctx, peerId, p.address, HELLO);
            scheduleRetry(ctx, peerId, p);
        });
    }

    private void onHello(LayerContext ctx, Envelope env, long src, byte[] b, int off, int len) {
        if (len >= 1 && b[off] == REKEY) {
            onRekey(ctx, env, src, len);
            return;
        }
        if (len < 3) {
            ctx.drop(env, "malformed-handshake", len + " bytes");
            return;
        }
        int type = b[off];
        int nameLen = Frames.getShort(b, off + 1);
        int signedLen = 1 + 2 + nameLen + 32 + 32 + 8;
        if ((type != HELLO && type != HELLO_REPLY) || len != signedLen + 64) {
            ctx.drop(env, "malformed-handshake", "type " + type + ", " + len + " bytes");
            return;
        }
        String name = new String(b, off + 3, nameLen, StandardCharsets.UTF_8);
        int p = off + 3 + nameLen;
        byte[] signingKey = Arrays.copyOfRange(b, p, p + 32);
        byte[] agreementKey = Arrays.copyOfRange(b, p + 32, p + 64);
        long ts = Frames.getLong(b, p + 64);
        if (Frames.id(name) != src) {
            ctx.drop(env, "masquerade", "a handshake for " + name + " from the frame id of another agent");
            return;
        }
        byte[] signed = new byte[signedLen + 8];
        System.arraycopy(b, off, signed, 0, signedLen);
        Frames.putLong(signed, signedLen, ownId);
        byte[] sig = Arrays.copyOfRange(b, off + signedLen, off + signedLen + 64);
        if (!Identity.verify(signingKey, signed, 0, signed.length, sig)) {
            ctx.drop(env, "masquerade", "the handshake of " + name + " is not signed by the key it presents");
            return;
        }
        long age = Math.abs(ctx.host().clock().epochMillis() - ts);
        if (age > config.handshakeWindowMs()) {
            ctx.drop(env, "stale", "a handshake " + age + " ms old (window " + config.handshakeWindowMs() + " ms)");
            return;
        }
        String pinKey = name.toLowerCase(Locale.ROOT);
        byte[] pinned = pins.get(pinKey);
        if (pinned == null) {
            pins.put(pinKey, signingKey);
        } else if (!MessageDigest.isEqual(pinned, signingKey)) {
            ctx.drop(env, "masquerade", name + " presented another identity key than the one it is known by");
            return;
        }
        Pair pair = pairs.computeIfAbsent(src, k -> new Pair());
        dropEvicted(ctx);
        pair.address = env.source();
        if (pair.key == null || !Arrays.equals(pair.peerAgreement, agreementKey)) {
            byte[] info = new byte[16 + 16];
            System.arraycopy("concord pair v1\0".getBytes(StandardCharsets.US_ASCII), 0, info, 0, 16);
            Frames.putLong(info, 16, Math.min(src, ownId));
            Frames.putLong(info, 24, Math.max(src, ownId));
            byte[] key = Crypto.hkdf(identity.agree(agreementKey), platformKeyBytes, info, 16);
            pair.key = new SecretKeySpec(key, "AES");
            pair.peerAgreement = agreementKey;
            try {
                pair.encrypt = Cipher.getInstance("AES/GCM/NoPadding");
                pair.decrypt = Cipher.getInstance("AES/GCM/NoPadding");
            } catch (GeneralSecurityException e) {
                throw new IllegalStateException("this JVM lacks AES-GCM: " + e.getMessage(), e);
            }
        }
        if (type == HELLO) {
            sendHello(ctx, src, env.source(), HELLO_REPLY);
        }
        if (pair.timer >= 0) {
            ctx.host().cancel(pair.timer);
            pair.timer = -1;
        }
        while (!pair.queue.isEmpty()) {
            Envelope queued = pair.queue.poll();
            seal(queued, Frames.PROTECTION_GCM_PAIR, 0, pair.key, pair.encrypt);
            ctx.passDown(queued);
        }
    }
}
