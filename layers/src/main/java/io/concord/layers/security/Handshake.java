package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.core.time.internal.LoopLimits;
import io.concord.core.time.internal.TokenBucket;
import io.concord.layers.frame.Frames;

import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Arrays;
import javax.crypto.spec.SecretKeySpec;

/**
 * The security layer's handshake (class 7, {@link SecurityLayer.Protection#GCM_PAIR}): a key per
 * pair of agents, agreed by X25519 in a hello, a reply and a confirmation that each side signs with
 * its Ed25519 identity; identities pinned on first use; the limits that keep strangers from
 * costing signatures or state (hello rates per agent and per loop, pins, pairs, rekey notices).
 * It keeps the pairs and the messages that wait for their key; the {@link FrameSealer} seals and
 * opens the frames with the keys it gives (JGroups keeps the same seam between its key exchanges
 * and {@code EncryptBase}). One per agent, called on its loop.
 */
final class Handshake {
    private static final int HELLO = Hello.HELLO;
    private static final int HELLO_REPLY = Hello.REPLY;
    /**
     * Key confirmation: the initiator proves it derived the key the reply's challenge gave, so the
     * responder starts using it. Until then the responder keeps the key it had.
     */
    private static final int CONFIRM = 4;
    private static final int CHALLENGE_BYTES = PairKeys.CHALLENGE_BYTES;
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
    /** REKEY notices sent at most a second, to all sources together. */
    static final int REKEY_NOTICES_PER_SECOND = RekeyLimit.NOTICES_PER_SECOND;
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

    private final SecurityLayer.Config config;
    private final FrameSealer sealer;
    private final long ownId;
    private final String ownName;
    private final Identity identity;
    private final SecureRandom random = new SecureRandom();
    private final Pins pins = new Pins();
    private final Pairs pairs = new Pairs();
    private TokenBucket hellos;
    /** The loop's hello budget, shared with its other agents; {@code null} on a host that offers none. */
    private TokenBucket loopHellos;
    private final RekeyLimit rekeys = new RekeyLimit();
    private long rekeysSent;
    private long hellosSent;

    /**
     * @param hellos      the agent's own hello budget ({@link #HELLO_BURST}, {@link #HELLOS_PER_SECOND}
     *                    but in tests)
     * @param loopHellos  the budget of the agent's loop, shared with its other agents; {@code null}
     *                    on a host that offers none
     */
    Handshake(SecurityLayer.Config config, FrameSealer sealer, long ownId, String ownName, Identity identity,
              TokenBucket hellos, TokenBucket loopHellos) {
        this.config = config;
        this.sealer = sealer;
        this.ownId = ownId;
        this.ownName = ownName;
        this.identity = identity;
        this.hellos = hellos;
        this.loopHellos = loopHellos;
    }

    /** The loop's hello budget, or {@code null}: asked of the host's {@link LoopLimits}. */
    static TokenBucket loopHellos(LoopLimits limits) {
        return limits == null ? null : limits.bucket("hellos", LOOP_HELLO_BURST, LOOP_HELLOS_PER_SECOND);
    }

    /**
     * A message to a peer: sealed with the pair's key, or held (bounded) while a handshake with the
     * peer runs, which it starts if none does.
     */
    void onDown(LayerContext ctx, Envelope env) {
        Pair p = pairs.getOrAdd(ctx, env.peerId());
        if (p.key != null) {
            sealer.seal(env, Frames.PROTECTION_GCM_PAIR, 0, p.key, p.encrypt);
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

    /**
     * Opens a frame sealed with a pair key; null if it does not open (dropped and counted): no
     * session key with its source (then at most one rekey notice a second asks for a handshake),
     * or a bad tag (the third in a row asks for a new handshake).
     */
    byte[] open(LayerContext ctx, Envelope env, long src, long ctr, byte[] d, int h, int len) {
        Pair p = pairs.get(src);
        if (p == null || (p.key == null && p.previousKey == null && p.pending.isEmpty())) {
            // Nothing here is authenticated yet: no state, no signature, and at most one
            // small notice back a second per source id (the sender, if real, then starts
            // the handshake, which costs it a signature first).
            ctx.drop(env, "no-session-key", "no session key with " + Long.toHexString(src)
                    + " (this agent restarted, or the frame is forged); asks the sender for a handshake");
            rekeyAtMostEverySecond(ctx, src, env.source());
            return null;
        }
        byte[] body = openWithPair(ctx, p, src, ctr, d, h, len);
        if (body == null) {
            if (++p.failures >= REHANDSHAKE_AFTER) {
                // The keys of the two ends differ (a confirmation lost, a key forgotten):
                // ask the peer, at the address it is known at, for a new handshake.
                p.failures = 0;
                rekeyAtMostEverySecond(ctx, src, p.address != null ? p.address : env.source());
            }
            ctx.drop(env, "bad-tag", "AES-GCM tag mismatch from " + env.source()
                    + ": forged, corrupted, or sealed with a key this agent does not hold");
            return null;
        }
        p.failures = 0;
        return body;
    }

    /**
     * Opens a frame with the pair's key, else the key before it, else a key a reply of this agent
     * gave and the peer has not confirmed yet (the frame confirms it). At most 2 + {@link #MAX_PENDING}
     * attempts, all bounded.
     */
    private byte[] openWithPair(LayerContext ctx, Pair p, long src, long ctr, byte[] d, int h, int len) {
        byte[] body;
        if (p.key != null && (body = sealer.open(p.decrypt, p.key, src, ctr, d, h, len)) != null) {
            return body;
        }
        if (p.previousKey != null && (body = sealer.open(p.previousDecrypt, p.previousKey, src, ctr, d, h, len)) != null) {
            return body;
        }
        for (Pair.Pending pending : p.pending) {
            if ((body = sealer.open(pending.decrypt(), pending.key(), src, ctr, d, h, len)) != null) {
                confirmed(ctx, src, p, pending);
                return body;
            }
        }
        return null;
    }

    private void rekeyAtMostEverySecond(LayerContext ctx, long src, Address to) {
        if (rekeys.allow(ctx, src)) {
            sendRekey(ctx, src, to);
        }
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
        sealer.sealWithPlatformKey(env, Frames.PROTECTION_GCM_PLATFORM, Frames.FLAG_HANDSHAKE);
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
        if (p.timer >= 0 || (p.lastRekeyAnswered != Long.MIN_VALUE && now - p.lastRekeyAnswered < RekeyLimit.EVERY_MS)) {
            ctx.drop(env, "rekey-limit", "a rekey notice from " + Long.toHexString(src)
                    + " while a handshake with it runs or within a second of the last");
            return;
        }
        p.lastRekeyAnswered = now;
        p.retire();
        if (p.address == null) {
            p.address = env.source();
        }
        startHandshake(ctx, src, p);
    }

    /** True once a session key with the peer exists. */
    boolean hasSessionWith(long peerId) {
        Pair p = pairs.get(peerId);
        return p != null && p.key != null;
    }

    /** REKEY notices sent (tests, the console). */
    long rekeysSent() {
        return rekeysSent;
    }

    /** Signed HELLOs and replies sent (tests, the console). */
    long hellosSent() {
        return hellosSent;
    }

    /** Pairs held. */
    int pairCount() {
        return pairs.size();
    }

    /** Signs and sends a hello ({@code echo == null}) or a reply; returns the signed body. */
    private byte[] sendHello(LayerContext ctx, long peerId, Address to, byte[] challenge) {
        return sendSigned(ctx, peerId, to, HELLO, challenge, null);
    }

    private byte[] sendSigned(LayerContext ctx, long peerId, Address to, int type, byte[] challenge, byte[] echo) {
        hellosSent++;
        byte[] body = Hello.write(identity, ownName, type, ctx.host().clock().epochMillis(), challenge, echo, peerId);
        sendHandshakeBody(ctx, peerId, to, body);
        return body;
    }

    private void sendHandshakeBody(LayerContext ctx, long peerId, Address to, byte[] body) {
        byte[] buf = new byte[Frames.HEADROOM + body.length + 40];
        System.arraycopy(body, 0, buf, Frames.HEADROOM, body.length);
        Envelope env = Envelope.control(peerId, to, buf, Frames.HEADROOM, body.length);
        sealer.sealWithPlatformKey(env, Frames.PROTECTION_GCM_PLATFORM, Frames.FLAG_HANDSHAKE);
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

    /** A handshake frame's body (hello, reply, confirmation or rekey notice), opened and checked. */
    void onHandshake(LayerContext ctx, Envelope env, long src, byte[] b, int off, int len) {
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
        int signedLen = Hello.signedLength(type, nameLen);
        if ((type != HELLO && type != HELLO_REPLY) || len != signedLen + 64) {
            ctx.drop(env, "malformed-handshake", "type " + type + ", " + len + " bytes");
            return;
        }
        Hello hello = Hello.read(b, off, type, nameLen);
        String name = hello.name();
        byte[] signingKey = hello.signingKey();
        byte[] agreementKey = hello.agreementKey();
        long ts = hello.timeMs();
        byte[] challenge = hello.challenge();
        byte[] echo = hello.echo();
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
            // A late answer to a hello of this agent's, not a replay, changes nothing: the peer answered
            // it more than once (a retry crossed its reply), or the hellos crossed and the peer's
            // handshake, which this agent answered, was confirmed first.
            if (known != null && (Arrays.equals(known.answeredChallenge, echo) || Arrays.equals(known.supersededChallenge, echo))) {
                ctx.drop(env, "handshake-late", "a reply from " + name + " to a hello of this agent answered already or made needless");
                return;
            }
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
        if (!hello.signedFor(b, off, signedLen, ownId)) {
            ctx.drop(env, "masquerade", "the handshake of " + name + " is not signed by the key it presents");
            return;
        }
        switch (pins.pin(name, signingKey)) {
            case FULL -> {
                ctx.drop(env, "pin-limit", Pins.MAX_PINS + " identities are pinned already; a handshake of a new name, "
                        + name + ", is refused");
                return;
            }
            case OTHER_KEY -> {
                ctx.drop(env, "masquerade", name + " presented another identity key than the one it is known by");
                return;
            }
            default -> {
                // pinned now, or pinned before with this key
            }
        }
        Pair pair = pairs.getOrAdd(ctx, src);
        if (type == HELLO_REPLY) {
            // Fresh: it echoes the challenge of our hello under way. Use the key, and confirm it.
            byte[] key = PairKeys.derive(identity.agree(agreementKey), sealer.platformKeyBytes(), ownId, src, pair.challenge, challenge);
            pair.address = env.source();
            byte[] confirm = new byte[1 + CHALLENGE_BYTES + 16];
            confirm[0] = (byte) CONFIRM;
            System.arraycopy(pair.challenge, 0, confirm, 1, CHALLENGE_BYTES);
            System.arraycopy(PairKeys.confirmation(key, pair.challenge, challenge), 0, confirm, 1 + CHALLENGE_BYTES, 16);
            pair.answeredChallenge = pair.challenge;
            pair.challenge = null;
            use(ctx, pair, key);
            sendHandshakeBody(ctx, src, pair.address, confirm);
            flush(ctx, pair);
            return;
        }
        for (Pair.Pending sent : pair.pending) {
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
        byte[] key = PairKeys.derive(identity.agree(agreementKey), sealer.platformKeyBytes(), ownId, src, challenge, replyChallenge);
        byte[] reply = sendSigned(ctx, src, env.source(), HELLO_REPLY, replyChallenge, challenge);
        if (pair.pending.size() >= MAX_PENDING) {
            pair.pending.poll();
        }
        pair.pending.add(new Pair.Pending(challenge, replyChallenge, key, reply));
    }

    /** Answers hellos at another rate: for tests. */
    void hellos(TokenBucket rate) {
        hellos = rate;
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
            for (Pair.Pending sent : pair.pending) {
                if (Arrays.equals(sent.helloChallenge(), hello)) {
                    if (!MessageDigest.isEqual(mac, PairKeys.confirmation(sent.keyBytes(), hello, sent.replyChallenge()))) {
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
    private void confirmed(LayerContext ctx, long src, Pair pair, Pair.Pending sent) {
        pair.pending.clear();
        pair.confirmedHello = sent.helloChallenge();
        if (pair.challenge != null) {
            pair.supersededChallenge = pair.challenge;
        }
        pair.challenge = null;
        use(ctx, pair, sent.keyBytes());
        flush(ctx, pair);
    }

    private void use(LayerContext ctx, Pair pair, byte[] key) {
        pair.retire();
        pair.key = new SecretKeySpec(key, "AES");
        pair.encrypt = FrameSealer.newGcm();
        pair.decrypt = FrameSealer.newGcm();
        pair.failures = 0;
        if (pair.timer >= 0) {
            ctx.host().cancel(pair.timer);
            pair.timer = -1;
        }
    }

    private void flush(LayerContext ctx, Pair pair) {
        while (!pair.queue.isEmpty()) {
            Envelope queued = pair.queue.poll();
            sealer.seal(queued, Frames.PROTECTION_GCM_PAIR, 0, pair.key, pair.encrypt);
            ctx.passDown(queued);
        }
    }
}
