package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.time.internal.LoopLimits;
import io.concord.core.time.internal.TokenBucket;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;

import java.security.SecureRandom;
import java.util.Set;

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
 *
 * <p>The layer is one layer of the stack, and two parts do its work: the {@link FrameSealer}
 * (header, safety code, tags, the memory of tags accepted) and, under class 7, the
 * {@link Handshake} (pair keys, pins, rekeying and the limits on strangers). This class checks a
 * frame's header and protection and passes it between them.
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

    /** REKEY notices sent at most a second, to all sources together. */
    static final int REKEY_NOTICES_PER_SECOND = Handshake.REKEY_NOTICES_PER_SECOND;

    private final Config config;
    private final boolean hmacTag;
    private final boolean safetyCode;
    /** The agent's hello budget, until the handshake takes it at {@link #init}. */
    private TokenBucket hellos = new TokenBucket(Handshake.HELLO_BURST, Handshake.HELLOS_PER_SECOND);
    private long ownId;
    private FrameSealer sealer;
    private Handshake handshake;
    private Identity identity;

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
        TokenBucket loopHellos = Handshake.loopHellos(ctx.host().capability(LoopLimits.class));
        String ownName = ctx.host().nodeName();
        ownId = Frames.id(ownName);
        long firstCounter = new SecureRandom().nextLong() & 0x3FFF_FFFF_FFFF_FFFFL;
        sealer = new FrameSealer(config.protection(), config.platformKey(), ownId, firstCounter, hmacTag, safetyCode);
        if (config.protection() == Protection.GCM_PAIR) {
            identity = config.identities().identityFor(ownName);
        }
        handshake = new Handshake(config, sealer, ownId, ownName, identity, hellos, loopHellos);
    }

    /**
     * Sets the counter of the next frame. Frames start from a random counter; only test vectors
     * need a known one. Never reuse a counter under one key.
     */
    public void setNextCounter(long next) {
        sealer.setNextCounter(next);
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
        return handshake.hasSessionWith(peerId);
    }

    /** REKEY notices sent (tests, the console). */
    public long rekeysSent() {
        return handshake.rekeysSent();
    }

    /** Signed HELLOs and replies sent (tests, the console). */
    public long hellosSent() {
        return handshake.hellosSent();
    }

    /** Pairs held. */
    public int pairCount() {
        return handshake.pairCount();
    }

    /** Answers hellos at another rate than the handshake's defaults: for tests. */
    void helloRate(int burst, int perSecond) {
        hellos = new TokenBucket(burst, perSecond);
        if (handshake != null) {
            handshake.hellos(hellos);
        }
    }

    // ---- down ---------------------------------------------------------------------------------------

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        if (env.peerId() == Frames.ANY) {
            // For whoever holds the port: no pair key can exist yet; the platform key seals it.
            Protection p = config.protection() == Protection.GCM_PAIR ? Protection.GCM_PLATFORM : config.protection();
            sealer.sealWithPlatformKey(env, p.bits, 0);
            ctx.passDown(env);
            return;
        }
        switch (config.protection()) {
            case CRC, HMAC, GCM_PLATFORM -> {
                sealer.sealWithPlatformKey(env, config.protection().bits, 0);
                ctx.passDown(env);
            }
            case GCM_PAIR -> handshake.onDown(ctx, env);
        }
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
        int keyBits = flags & Frames.KEY_ID_MASK;
        int protection = flags & Frames.PROTECTION_MASK;
        if (protection == Frames.PROTECTION_CRC && keyBits != 0) {
            ctx.drop(env, "malformed-frame", "a key id on a frame without a key (flags " + Integer.toHexString(flags) + ")");
            return;
        }
        boolean handshakeFrame = (flags & Frames.FLAG_HANDSHAKE) != 0;
        long src = Frames.getLong(d, h + 4);
        long dst = Frames.getLong(d, h + 12);
        long ctr = Frames.getLong(d, h + 20);
        boolean any = dst == Frames.ANY;
        if (dst != ownId && !any) {
            ctx.drop(env, "misdirected", "the frame is for agent id " + Long.toHexString(dst) + ", not for this one");
            return;
        }
        if (any && handshakeFrame) {
            ctx.drop(env, "malformed-frame", "a handshake addressed to any agent");
            return;
        }
        if (handshakeFrame && config.protection() != Protection.GCM_PAIR) {
            ctx.drop(env, "unprotected", "a handshake, but this agent does not use per-pair keys");
            return;
        }
        int required = handshakeFrame || (any && config.protection() == Protection.GCM_PAIR)
                ? Frames.PROTECTION_GCM_PLATFORM : config.protection().bits;
        if (protection != required) {
            ctx.drop(env, "unprotected", "protection " + protection + " where " + required + " is required");
            return;
        }
        if (protection != Frames.PROTECTION_CRC && keyBits != sealer.keyBits()) {
            // Sealed under another key: most often another platform sharing this port range on the
            // machine (its discovery asks every port). Skipped before any MAC is computed.
            ctx.drop(env, "foreign-key", "a frame sealed under another platform's key (key id " + (keyBits >> 3) + ", this platform's "
                    + (sealer.keyBits() >> 3) + ") from " + env.source() + ": another platform shares this port range, or a forgery; skipped");
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
            if (sealer.seenTag(tagKey)) {
                ctx.drop(env, "copy", "a copy of a frame already accepted");
                return;
            }
            if (protection == Frames.PROTECTION_HMAC) {
                if (!sealer.hmacMatches(d, h, len)) {
                    ctx.drop(env, "bad-tag", "HMAC mismatch from " + env.source() + ": forged, corrupted, or another platform key");
                    return;
                }
                body = d;
                bodyOff = h + Frames.HEADER_BYTES;
                bodyLen = len - Frames.HEADER_BYTES - Frames.CRC_BYTES - Frames.TAG_BYTES;
            } else {
                if (protection == Frames.PROTECTION_GCM_PAIR) {
                    body = handshake.open(ctx, env, src, ctr, d, h, len);
                    if (body == null) {
                        return;
                    }
                } else {
                    body = sealer.openWithPlatformKey(src, ctr, d, h, len);
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
        if (!sealer.safetyCodeMatches(d, h, body, bodyOff, bodyLen)) {
            ctx.drop(env, "corrupt", "the safety code does not match: the frame was damaged");
            return;
        }
        if (tagKey != 0) {
            sealer.rememberTag(tagKey);
        }
        if (handshakeFrame) {
            handshake.onHandshake(ctx, env, src, body, bodyOff, bodyLen);
            return;
        }
        env.setPeerId(src);
        env.setData(body, bodyOff, bodyLen);
        if (any) {
            env.putHeader(Frames.ENVELOPE_ANY, Boolean.TRUE);
        }
        ctx.passUp(env);
    }
}
