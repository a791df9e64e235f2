package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.core.time.LoopLimits;
import io.concord.core.time.TokenBucket;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.zip.CRC32C;
import javax.crypto.Cipher;
import javax.crypto.Mac;
import javax.crypto.spec.GCMParameterSpec;
import javax.crypto.spec.SecretKeySpec;

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
     * Key confirmation: the initiator proves it derived the key the reply's challenge gave, so the
     * responder starts using it. Until then the responder keeps the key it had.
     */
    private static final int CONFIRM = 4;
    private static final int CHALLENGE_BYTES = 16;
    /** Replies a responder keeps waiting for confirmation, per peer (older ones are forgotten). */
    private static final int MAX_PENDING = 4;
    /** Frames in a row from a peer that fail authentication before it is asked for a new handshake. */
    private static final int REHANDSHAKE_AFTER = 3;
    /**
     * A notice, sealed with the platform key and not signed: "I hold no session key with you;
     * start a handshake". What a receiver sends, at most once a second per source, for a frame
     * sealed with a pair key it does not have (it restarted, or the frame is forged).
     */
    private static final int REKEY = 3;
    private static final long REKEY_EVERY_MS = 1_000;
    private static final int REKEY_MEMORY = 1024;
    /** REKEY notices sent at most a second, to all sources together. */
    static final int REKEY_NOTICES_PER_SECOND = 64;
    private static final int RECENT_TAGS = 64;
    private static final int MAX_PAIRS = 4096;
    /**
     * Identities pinned. At the limit a new name's handshake is refused rather than an old pin
     * forgotten: forgetting one would let a holder of the platform key who floods new names take
     * over a real agent's name with another identity.
     */
    static final int MAX_PINS = 16_384;
    /**
     * Hellos answered at most: {@link #HELLO_BURST} at once, then {@link #HELLOS_PER_SECOND}. Each
     * costs a signature check, a key agreement and a signature; a holder of the platform key can
     * send them under new names as fast as it can sign. A platform's start needs one per peer an
     * agent talks to (a container: one per member), well within the burst; past it, a hello is
     * dropped before any signature work ({@code handshake-limit}) and its sender tries again.
     */
    static final int HELLO_BURST = 256;
    static final int HELLOS_PER_SECOND = 64;
    /**
     * ... and by all the agents of one loop together (the runtime's {@link LoopLimits}):
     * the loop's time is what the signature work takes, so its bound must not grow with the number
     * of agents the loop runs (100 agents at 64 a second each would be its whole time).
     */
    static final int LOOP_HELLO_BURST = 1024;
    static final int LOOP_HELLOS_PER_SECOND = 128;
    private static final long FIRST_RETRY_MS = 100;
    private static final int MAX_HELLO_ATTEMPTS = 10;

    private final Config config;
    private final boolean hmacTag;
    private final boolean safetyCode;
    private final SecureRandom random = new SecureRandom();
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
    private final List<Pair> evicted = new ArrayList<>();
    /** When a REKEY notice last went to each source id (bounded: forgetting one costs a notice). */
    private final Map<Long, Long> rekeyed = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Long> eldest) {
            return size() > REKEY_MEMORY;
        }
    };
    private TokenBucket hellos = new TokenBucket(HELLO_BURST, HELLOS_PER_SECOND);
    /** The loop's hello budget, shared with its other agents; {@code null} on a host that offers none. */
    private TokenBucket loopHellos;
    private final TokenBucket rekeys = new TokenBucket(REKEY_NOTICES_PER_SECOND,
            REKEY_NOTICES_PER_SECOND);
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
        /** The key in use, confirmed by both ends; null while none is. */
        SecretKeySpec key;
        // One cipher per key and direction: the JDK expands an AES key again whenever a cipher is
        // initialised with another key than last time, which would cost more than the encryption.
        Cipher encrypt;
        Cipher decrypt;
        /** The key before, still opened for frames under way while a new one was agreed. */
        SecretKeySpec previousKey;
        Cipher previousDecrypt;
        Address address;
        final ArrayDeque<Envelope> queue = new ArrayDeque<>();
        long timer = -1;
        int attempts;
        /** The challenge of this agent's hello under way, or null. */
        byte[] challenge;
        /** Replies this agent sent, each waiting for the peer's confirmation. */
        final ArrayDeque<Pending> pending = new ArrayDeque<>();
        /** The challenge of the last hello whose key was confirmed: a copy of it is a replay. */
        byte[] confirmedHello;
        int failures;
        long lastRekeyAnswered = Long.MIN_VALUE;
    }

    /** A reply sent and not yet confirmed: the key it gives (and its cipher), and the signed reply to send again. */
    private record Pending(byte[] helloChallenge, byte[] replyChallenge, byte[] keyBytes, SecretKeySpec key, Cipher decrypt,
                           byte[] reply) {
        Pending(byte[] helloChallenge, byte[] replyChallenge, byte[] keyBytes, byte[] reply) {
            this(helloChallenge, replyChallenge, keyBytes, new SecretKeySpec(keyBytes, "AES"), newGcm(), reply);
        }
    }

    public SecurityLayer(Config config) {
        this(config, Set.of());
    }

    /**
     * A security layer with some defences off: only for the threat tests, through
     * {@code SafetyStack.Builder.withoutDefences}, above the layers.
     */
    public SecurityLayer(Config config, Set<Defence> off) {
        this.config = config;
        this.hmacTag = !off.contains(Defence.HMAC_TAG);
        this.safetyCode = !off.contains(Defence.SAFETY_CODE);
    }

    @Override
    public String name() {
        return "security";
    }

    @Override
    public void init(LayerContext ctx) {
        LoopLimits limits = ctx.host().capability(LoopLimits.class);
        loopHellos = limits == null ? null : limits.bucket("hellos", LOOP_HELLO_BURST, LOOP_HELLOS_PER_SECOND);
        ownName = ctx.host().nodeName();
        ownId = Frames.id(ownName);
        counter = new SecureRandom().nextLong() & 0x3FFF_FFFF_FFFF_FFFFL;
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
                if (hmacTag && !MessageDigest.isEqual(Arrays.copyOf(expected, Frames.TAG_BYTES),
                        Arrays.copyOfRange(d, h + len - Frames.TAG_BYTES, h + len))) {
                    ctx.drop(env, "bad-tag", "HMAC mismatch from " + env.source() + ": forged, corrupted, or another platform key");
                    return;
                }
                body = d;
                bodyOff = h + Frames.HEADER_BYTES;
                bodyLen = len - Frames.HEADER_BYTES - Frames.CRC_BYTES - Frames.TAG_BYTES;
            } else {
                if (protection == Frames.PROTECTION_GCM_PAIR) {
                    Pair p = pairs.get(src);
                    if (p == null || (p.key == null && p.previousKey == null && p.pending.isEmpty())) {
                        // Nothing here is authenticated yet: no state, no signature, and at most one
                        // small notice back a second per source id (the sender, if real, then starts
                        // the handshake, which costs it a signature first).
                        ctx.drop(env, "no-session-key", "no session key with " + Long.toHexString(src)
                                + " (this agent restarted, or the frame is forged); asks the sender for a handshake");
                        rekeyAtMostEverySecond(ctx, src, env.source());
                        return;
                    }
                    body = openWithPair(ctx, p, src, ctr, d, h, len);
                    if (body == null) {
                        if (++p.failures >= REHANDSHAKE_AFTER) {
                            // The keys of the two ends differ (a confirmation lost, a key forgotten):
                            // ask the peer, at the address it is known at, for a new handshake.
                            p.failures = 0;
                            rekeyAtMostEverySecond(ctx, src, p.address != null ? p.address : env.source());
                        }
                        ctx.drop(env, "bad-tag", "AES-GCM tag mismatch from " + env.source()
                                + ": forged, corrupted, or sealed with a key this agent does not hold");
                        return;
                    }
                    p.failures = 0;
                } else {
                    body = open(platformDecrypt, platformAead, src, ctr, d, h, len);
                    if (body == null) {
                        ctx.drop(env, "bad-tag", "AES-GCM tag mismatch from " + env.source()
                                + ": forged, corrupted, replayed under an old key, or another platform key");
                        return;
                    }
                }
                bodyOff = 0;
                bodyLen = body.length - Frames.CRC_BYTES;
            }
        }
        crc.reset();
        crc.update(d, h, Frames.HEADER_BYTES);
        crc.update(body, bodyOff, bodyLen);
        if (safetyCode && (int) crc.getValue() != Frames.getInt(body, bodyOff + bodyLen)) {
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

    /** Opens an AES-GCM frame, or returns null if the tag does not match. */
    private byte[] open(Cipher gcm, SecretKeySpec key, long src, long ctr, byte[] d, int h, int len) {
        try {
            nonceFor(src, ctr);
            gcm.init(Cipher.DECRYPT_MODE, key, new GCMParameterSpec(128, nonce));
            gcm.updateAAD(d, h, Frames.HEADER_BYTES);
            return gcm.doFinal(d, h + Frames.HEADER_BYTES, len - Frames.HEADER_BYTES);
        } catch (GeneralSecurityException e) {
            return null; // a bad tag (AEADBadTagException), or a frame the cipher refuses
        }
    }

    /**
     * Opens a frame with the pair's key, else the key before it, else a key a reply of this agent
     * gave and the peer has not confirmed yet (the frame confirms it). At most 2 + {@link #MAX_PENDING}
     * attempts, all bounded.
     */
    private byte[] openWithPair(LayerContext ctx, Pair p, long src, long ctr, byte[] d, int h, int len) {
        byte[] body;
        if (p.key != null && (body = open(p.decrypt, p.key, src, ctr, d, h, len)) != null) {
            return body;
        }
        if (p.previousKey != null && (body = open(p.previousDecrypt, p.previousKey, src, ctr, d, h, len)) != null) {
            return body;
        }
        for (Pending pending : p.pending) {
            if ((body = open(pending.decrypt(), pending.key(), src, ctr, d, h, len)) != null) {
                confirmed(ctx, src, p, pending);
                return body;
            }
        }
        return null;
    }

    private void rekeyAtMostEverySecond(LayerContext ctx, long src, Address to) {
        long now = ctx.host().clock().epochMillis();
        Long last = rekeyed.get(src);
        if (last == null || now - last >= REKEY_EVERY_MS) {
            // ... and at most REKEY_NOTICES_PER_SECOND in all: forged frames with a new source id
            // each would otherwise cost a sealed notice and a send apiece.
            if (!rekeys.take(ctx.nowNs())) {
                return;
            }
            rekeyed.put(src, now);
            sendRekey(ctx, src, to);
        }
    }

    private static Cipher newGcm() {
        try {
            return Cipher.getInstance("AES/GCM/NoPadding");
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM lacks AES-GCM: " + e.getMessage(), e);
        }
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
    //
    // initiator                                   responder
    //   HELLO(name, keys, time, challenge I)  ->    a key from I and a fresh R, kept pending
    //                                         <-    REPLY(name, keys, time, R, echo of I)
    //   the echo of I proves the reply fresh:
    //   the key is used, and confirmed         ->    CONFIRM(I, MAC of I and R): the key is used
    //
    // Both challenges go into the key, so a replayed hello (or a replayed reply) gives a key
    // nobody holds and changes nothing in use; old frames never open under a new key.

    /** Sends a hello and keeps repeating it until answered, unless a handshake is already running. */
    private void startHandshake(LayerContext ctx, long peerId, Pair p) {
        if (p.timer < 0) {
            p.attempts = 0;
            p.challenge = new byte[CHALLENGE_BYTES];
            random.nextBytes(p.challenge);
            sendHello(ctx, peerId, p.address, p.challenge);
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

    /**
     * A peer holds no key with this agent, or cannot open its frames: agree a new one. Our frames
     * wait meanwhile, and the old key still opens the peer's frames under way. Anyone with the
     * platform key can send this notice, so it is answered at most once a second per peer.
     */
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
        long now = ctx.host().clock().epochMillis();
        if (p.timer >= 0 || (p.lastRekeyAnswered != Long.MIN_VALUE && now - p.lastRekeyAnswered < REKEY_EVERY_MS)) {
            ctx.drop(env, "rekey-limit", "a rekey notice from " + Long.toHexString(src)
                    + " while a handshake with it runs or within a second of the last");
            return;
        }
        p.lastRekeyAnswered = now;
        retire(p);
        if (p.address == null) {
            p.address = env.source();
        }
        startHandshake(ctx, src, p);
    }

    /** The key in use becomes the previous one: still opened, no longer used to seal. */
    private static void retire(Pair p) {
        if (p.key != null) {
            p.previousKey = p.key;
            p.previousDecrypt = p.decrypt;
        }
        p.key = null;
        p.encrypt = null;
        p.decrypt = null;
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

    /** Signs and sends a hello ({@code echo == null}) or a reply; returns the signed body. */
    private byte[] sendHello(LayerContext ctx, long peerId, Address to, byte[] challenge) {
        return sendSigned(ctx, peerId, to, HELLO, challenge, null);
    }

    private byte[] sendSigned(LayerContext ctx, long peerId, Address to, int type, byte[] challenge, byte[] echo) {
        hellosSent++;
        byte[] name = ownName.getBytes(StandardCharsets.UTF_8);
        int signedLen = 1 + 2 + name.length + 32 + 32 + 8 + CHALLENGE_BYTES + (echo != null ? CHALLENGE_BYTES : 0);
        byte[] signed = new byte[signedLen + 8];
        signed[0] = (byte) type;
        Frames.putShort(signed, 1, name.length);
        System.arraycopy(name, 0, signed, 3, name.length);
        int p = 3 + name.length;
        System.arraycopy(identity.signingPublicKey(), 0, signed, p, 32);
        System.arraycopy(identity.agreementPublicKey(), 0, signed, p + 32, 32);
        Frames.putLong(signed, p + 64, ctx.host().clock().epochMillis());
        System.arraycopy(challenge, 0, signed, p + 72, CHALLENGE_BYTES);
        if (echo != null) {
            System.arraycopy(echo, 0, signed, p + 72 + CHALLENGE_BYTES, CHALLENGE_BYTES);
        }
        // The signature also covers the destination id, so a hello cannot be replayed to another agent.
        Frames.putLong(signed, signedLen, peerId);
        byte[] sig = identity.sign(signed, 0, signedLen + 8);
        byte[] body = Arrays.copyOf(signed, signedLen + 64);
        System.arraycopy(sig, 0, body, signedLen, 64);
        sendHandshakeBody(ctx, peerId, to, body);
        return body;
    }

    private void sendHandshakeBody(LayerContext ctx, long peerId, Address to, byte[] body) {
        byte[] buf = new byte[Frames.HEADROOM + body.length + 40];
        System.arraycopy(body, 0, buf, Frames.HEADROOM, body.length);
        Envelope env = Envelope.control(peerId, to, buf, Frames.HEADROOM, body.length);
        seal(env, Frames.PROTECTION_GCM_PLATFORM, Frames.FLAG_HANDSHAKE, platformAead, platformEncrypt);
        ctx.passDown(env);
    }

    private void scheduleRetry(LayerContext ctx, long peerId, Pair p) {
        long delayMs = Math.min(2_000, FIRST_RETRY_MS << Math.min(p.attempts, 5));
        p.timer = ctx.host().schedule(ctx.nowNs() + delayMs * 1_000_000L, () -> {
            p.timer = -1;
            if (p.key != null || p.challenge == null) {
                return;
            }
            if (++p.attempts >= MAX_HELLO_ATTEMPTS) {
                for (Envelope e : p.queue) {
                    ctx.drop(e, "no-handshake", "peer " + Long.toHexString(peerId) + " at " + p.address
                            + " did not answer " + MAX_HELLO_ATTEMPTS + " handshakes");
                }
                p.queue.clear();
                p.challenge = null;
                return;
            }
            sendHello(ctx, peerId, p.address, p.challenge);
            scheduleRetry(ctx, peerId, p);
        });
    }

    private void onHello(LayerContext ctx, Envelope env, long src, byte[] b, int off, int len) {
        if (len >= 1 && b[off] == REKEY) {
            onRekey(ctx, env, src, len);
            return;
        }
        if (len >= 1 && b[off] == CONFIRM) {
            onConfirm(ctx, env, src, b, off, len);
            return;
        }
        if (len < 3) {
            ctx.drop(env, "malformed-handshake", len + " bytes");
            return;
        }
        int type = b[off];
        int nameLen = Frames.getShort(b, off + 1);
        int signedLen = 1 + 2 + nameLen + 32 + 32 + 8 + CHALLENGE_BYTES + (type == HELLO_REPLY ? CHALLENGE_BYTES : 0);
        if ((type != HELLO && type != HELLO_REPLY) || len != signedLen + 64) {
            ctx.drop(env, "malformed-handshake", "type " + type + ", " + len + " bytes");
            return;
        }
        String name = new String(b, off + 3, nameLen, StandardCharsets.UTF_8);
        int p = off + 3 + nameLen;
        byte[] signingKey = Arrays.copyOfRange(b, p, p + 32);
        byte[] agreementKey = Arrays.copyOfRange(b, p + 32, p + 64);
        long ts = Frames.getLong(b, p + 64);
        byte[] challenge = Arrays.copyOfRange(b, p + 72, p + 72 + CHALLENGE_BYTES);
        byte[] echo = type == HELLO_REPLY ? Arrays.copyOfRange(b, p + 72 + CHALLENGE_BYTES, p + 72 + 2 * CHALLENGE_BYTES) : null;
        if (Frames.id(name) != src) {
            ctx.drop(env, "masquerade", "a handshake for " + name + " from the frame id of another agent");
            return;
        }
        Pair known = pairs.get(src);
        if (type == HELLO && known != null && known.confirmedHello != null && Arrays.equals(known.confirmedHello, challenge)) {
            ctx.drop(env, "replayed-handshake", "a copy of the hello of " + name + " whose key is in use");
            return;
        }
        if (type == HELLO_REPLY && (known == null || known.challenge == null || !Arrays.equals(known.challenge, echo))) {
            ctx.drop(env, "replayed-handshake", "a reply from " + name + " to no hello of this agent under way");
            return;
        }
        // Cheap refusals first: a stale time needs no signature checked to be refused (a changed
        // one fails the signature below).
        long age = Math.abs(ctx.host().clock().epochMillis() - ts);
        if (age > config.handshakeWindowMs()) {
            ctx.drop(env, "stale", "a handshake " + age + " ms old (window " + config.handshakeWindowMs() + " ms)");
            return;
        }
        if (type == HELLO) {
            TokenBucket over = !hellos.take(ctx.nowNs()) ? hellos
                    : loopHellos != null && !loopHellos.take(ctx.nowNs()) ? loopHellos : null;
            if (over != null) {
                ctx.drop(env, "handshake-limit", "more hellos than " + over.burst() + " at once and " + (int) over.perSecond()
                        + " a second" + (over == loopHellos ? " to the agents of this loop together" : "") + "; the hello of "
                        + name + " is not answered (its sender tries again)");
                return;
            }
        }
        byte[] signed = new byte[signedLen + 8];
        System.arraycopy(b, off, signed, 0, signedLen);
        Frames.putLong(signed, signedLen, ownId);
        byte[] sig = Arrays.copyOfRange(b, off + signedLen, off + signedLen + 64);
        if (!Identity.verify(signingKey, signed, 0, signed.length, sig)) {
            ctx.drop(env, "masquerade", "the handshake of " + name + " is not signed by the key it presents");
            return;
        }
        String pinKey = name.toLowerCase(Locale.ROOT);
        byte[] pinned = pins.get(pinKey);
        if (pinned == null) {
            if (pins.size() >= MAX_PINS) {
                ctx.drop(env, "pin-limit", MAX_PINS + " identities are pinned already; a handshake of a new name, "
                        + name + ", is refused");
                return;
            }
            pins.put(pinKey, signingKey);
        } else if (!MessageDigest.isEqual(pinned, signingKey)) {
            ctx.drop(env, "masquerade", name + " presented another identity key than the one it is known by");
            return;
        }
        Pair pair = pairs.computeIfAbsent(src, k -> new Pair());
        dropEvicted(ctx);
        if (type == HELLO_REPLY) {
            // Fresh: it echoes the challenge of our hello under way. Use the key, and confirm it.
            byte[] key = pairKey(identity.agree(agreementKey), src, pair.challenge, challenge);
            pair.address = env.source();
            byte[] confirm = new byte[1 + CHALLENGE_BYTES + 16];
            confirm[0] = (byte) CONFIRM;
            System.arraycopy(pair.challenge, 0, confirm, 1, CHALLENGE_BYTES);
            System.arraycopy(confirmation(key, pair.challenge, challenge), 0, confirm, 1 + CHALLENGE_BYTES, 16);
            pair.challenge = null;
            use(ctx, pair, key);
            sendHandshakeBody(ctx, src, pair.address, confirm);
            flush(ctx, pair);
            return;
        }
        for (Pending sent : pair.pending) {
            if (Arrays.equals(sent.helloChallenge(), challenge)) {
                // The initiator repeats its hello: our reply was lost. The same reply again, unsigned anew.
                sendHandshakeBody(ctx, src, env.source(), sent.reply());
                return;
            }
        }
        if (pair.challenge != null && pair.key == null && ownId < src) {
            // Both started at once: the smaller id's handshake goes on, and the peer answers it.
            ctx.drop(env, "crossed-handshake", name + " started a handshake while this agent's own runs; the smaller id's goes on");
            return;
        }
        // A hello of our own under way goes on: if the peer never confirms (it had nothing to
        // send, and the confirmation was lost), its reply gives us a key all the same.
        if (pair.address == null || pair.key == null) {
            pair.address = env.source();
        }
        byte[] replyChallenge = new byte[CHALLENGE_BYTES];
        random.nextBytes(replyChallenge);
        byte[] key = pairKey(identity.agree(agreementKey), src, challenge, replyChallenge);
        byte[] reply = sendSigned(ctx, src, env.source(), HELLO_REPLY, replyChallenge, challenge);
        if (pair.pending.size() >= MAX_PENDING) {
            pair.pending.poll();
        }
        pair.pending.add(new Pending(challenge, replyChallenge, key, reply));
    }

    /** Answers hellos at another rate than {@link #HELLO_BURST} and {@link #HELLOS_PER_SECOND}: for tests. */
    void helloRate(int burst, int perSecond) {
        hellos = new TokenBucket(burst, perSecond);
    }

    /** The initiator derived the key of one of our replies: use it. */
    private void onConfirm(LayerContext ctx, Envelope env, long src, byte[] b, int off, int len) {
        if (len != 1 + CHALLENGE_BYTES + 16) {
            ctx.drop(env, "malformed-handshake", "a confirmation of " + len + " bytes");
            return;
        }
        Pair pair = pairs.get(src);
        byte[] hello = Arrays.copyOfRange(b, off + 1, off + 1 + CHALLENGE_BYTES);
        byte[] mac = Arrays.copyOfRange(b, off + 1 + CHALLENGE_BYTES, off + len);
        if (pair != null) {
            for (Pending sent : pair.pending) {
                if (Arrays.equals(sent.helloChallenge(), hello)) {
                    if (!MessageDigest.isEqual(mac, confirmation(sent.keyBytes(), hello, sent.replyChallenge()))) {
                        break;
                    }
                    confirmed(ctx, src, pair, sent);
                    return;
                }
            }
        }
        ctx.drop(env, "replayed-handshake", "a confirmation from " + Long.toHexString(src)
                + " of no reply of this agent waiting for one, or with the wrong proof");
    }

    /** The peer holds the key of one of our replies: it is the pair's key from now on. */
    private void confirmed(LayerContext ctx, long src, Pair pair, Pending sent) {
        pair.pending.clear();
        pair.confirmedHello = sent.helloChallenge();
        pair.challenge = null;
        use(ctx, pair, sent.keyBytes());
        flush(ctx, pair);
    }

    private void use(LayerContext ctx, Pair pair, byte[] key) {
        retire(pair);
        pair.key = new SecretKeySpec(key, "AES");
        pair.encrypt = newGcm();
        pair.decrypt = newGcm();
        pair.failures = 0;
        if (pair.timer >= 0) {
            ctx.host().cancel(pair.timer);
            pair.timer = -1;
        }
    }

    private void flush(LayerContext ctx, Pair pair) {
        while (!pair.queue.isEmpty()) {
            Envelope queued = pair.queue.poll();
            seal(queued, Frames.PROTECTION_GCM_PAIR, 0, pair.key, pair.encrypt);
            ctx.passDown(queued);
        }
    }

    /** HKDF of the shared secret, salted with the platform key, bound to both ids and both challenges. */
    private byte[] pairKey(byte[] shared, long peerId, byte[] helloChallenge, byte[] replyChallenge) {
        byte[] info = new byte[16 + 16 + 2 * CHALLENGE_BYTES];
        System.arraycopy("concord pair v2\0".getBytes(StandardCharsets.US_ASCII), 0, info, 0, 16);
        Frames.putLong(info, 16, Math.min(peerId, ownId));
        Frames.putLong(info, 24, Math.max(peerId, ownId));
        System.arraycopy(helloChallenge, 0, info, 32, CHALLENGE_BYTES);
        System.arraycopy(replyChallenge, 0, info, 32 + CHALLENGE_BYTES, CHALLENGE_BYTES);
        return Crypto.hkdf(shared, platformKeyBytes, info, 16);
    }

    /** The proof of holding a pair key: HMAC-SHA256 of both challenges under it, 16 bytes. */
    private static byte[] confirmation(byte[] key, byte[] helloChallenge, byte[] replyChallenge) {
        try {
            Mac m = Mac.getInstance("HmacSHA256");
            m.init(new SecretKeySpec(key, "HmacSHA256"));
            m.update("concord confirm v1".getBytes(StandardCharsets.US_ASCII));
            m.update(helloChallenge);
            m.update(replyChallenge);
            return Arrays.copyOf(m.doFinal(), 16);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM lacks HMAC-SHA256: " + e.getMessage(), e);
        }
    }
}
