package io.concord.layers.temporal;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;

import java.util.Set;

/**
 * The temporal layer: stamps every frame with the platform time and drops frames whose stamp lies
 * outside the acceptance window ({@code stale}: delayed or replayed late; {@code from-future}: a
 * clock far ahead). It also keeps the agent's {@link PlatformClock}: every sync interval it asks
 * the time source for its time, NTP-fashion (t1 sent, t2 received there, t3 sent back, t4
 * received), and takes offset = ((t2 - t1) + (t3 - t4)) / 2 from the exchange with the shortest
 * round trip of the last few.
 *
 * <p>Header: kind u8 (0 data, 1 time request, 2 time response) and the stamp, i64 microseconds.
 * A time response carries t1, t2 and t3 after it.
 */
public final class TemporalLayer extends Layer {
    public static final int HEADER_BYTES = 9;
    private static final int DATA = 0;
    private static final int TIME_REQUEST = 1;
    private static final int TIME_RESPONSE = 2;

    /**
     * @param acceptanceWindowMs how far a stamp may lie from the platform time
     * @param timeSourceId       the frame id of the time source, or 0 for none
     * @param timeSource         its address, or {@code null}
     * @param syncIntervalMs     how often to ask it
     */
    public record Config(long acceptanceWindowMs, long timeSourceId, Address timeSource, long syncIntervalMs) {
        public Config {
            if (acceptanceWindowMs <= 0) {
                throw new IllegalArgumentException("the acceptance window must be > 0 ms, got " + acceptanceWindowMs);
            }
            if ((timeSource == null) != (timeSourceId == 0)) {
                throw new IllegalArgumentException("give both the time source's id and its address, or neither");
            }
            if (timeSource != null && syncIntervalMs <= 0) {
                throw new IllegalArgumentException("the sync interval must be > 0 ms, got " + syncIntervalMs);
            }
        }

        /** A window and no time source. */
        public static Config window(long acceptanceWindowMs) {
            return new Config(acceptanceWindowMs, 0, null, 0);
        }
    }

    private final Config config;
    private final boolean acceptanceWindow;
    private final PlatformClock clock;
    private long pendingT1 = Long.MIN_VALUE;
    private long bestRoundTripUs = Long.MAX_VALUE;
    private int exchanges;

    public TemporalLayer(Config config, PlatformClock clock) {
        this(config, clock, Set.of());
    }

    /**
     * A temporal layer with some defences off: only for the threat tests, through
     * {@code SafetyStack.Builder.withoutDefences}, above the layers.
     */
    public TemporalLayer(Config config, PlatformClock clock, Set<Defence> off) {
        this.acceptanceWindow = !off.contains(Defence.ACCEPTANCE_WINDOW);
        this.config = config;
        this.clock = clock;
    }

    @Override
    public String name() {
        return "temporal";
    }

    public PlatformClock clock() {
        return clock;
    }

    @Override
    public void init(LayerContext ctx) {
        clock.bind(ctx.host().clock());
        ctx.host().setPlatformTime(clock::nowMs);
    }

    @Override
    public void start(LayerContext ctx) {
        if (config.timeSource() != null) {
            sync(ctx);
        }
    }

    private void sync(LayerContext ctx) {
        pendingT1 = clock.nowUs();
        byte[] b = new byte[Frames.HEADROOM + HEADER_BYTES + 40];
        b[Frames.HEADROOM] = TIME_REQUEST;
        Frames.putLong(b, Frames.HEADROOM + 1, pendingT1);
        ctx.passDown(Envelope.control(config.timeSourceId(), config.timeSource(), b, Frames.HEADROOM, HEADER_BYTES));
        // Sync quickly at first, then at the configured interval.
        long next = exchanges < 4 ? Math.min(200, config.syncIntervalMs()) : config.syncIntervalMs();
        ctx.host().schedule(ctx.nowNs() + next * 1_000_000L, () -> sync(ctx));
    }

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        int at = env.prepend(HEADER_BYTES);
        byte[] d = env.data();
        d[at] = DATA;
        Frames.putLong(d, at + 1, clock.nowUs());
        ctx.passDown(env);
    }

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        if (env.length() < HEADER_BYTES) {
            ctx.drop(env, "malformed-frame", "no temporal header");
            return;
        }
        byte[] d = env.data();
        int o = env.offset();
        int kind = d[o];
        long stamp = Frames.getLong(d, o + 1);
        long now = clock.nowUs();
        long windowUs = config.acceptanceWindowMs() * 1_000L;
        if (!acceptanceWindow) {
            windowUs = Long.MAX_VALUE / 2;
        }
        if (now - stamp > windowUs) {
            ctx.drop(env, "stale", "stamped " + (now - stamp) / 1_000 + " ms ago, beyond the " + config.acceptanceWindowMs()
                    + " ms window: delayed or replayed");
            return;
        }
        if (stamp - now > windowUs) {
            ctx.drop(env, "from-future", "stamped " + (stamp - now) / 1_000 + " ms ahead of the platform clock; "
                    + "is the sender's clock wrong, or ours not synchronised?");
            return;
        }
        switch (kind) {
            case DATA -> {
                env.skip(HEADER_BYTES);
                ctx.passUp(env);
            }
            case TIME_REQUEST -> answerTime(ctx, env, stamp, now);
            case TIME_RESPONSE -> onTimeResponse(ctx, env, now);
            default -> ctx.drop(env, "malformed-frame", "unknown temporal kind " + kind);
        }
    }

    private void answerTime(LayerContext ctx, Envelope req, long t1, long t2) {
        byte[] b = new byte[Frames.HEADROOM + HEADER_BYTES + 24 + 40];
        int o = Frames.HEADROOM;
        b[o] = TIME_RESPONSE;
        Frames.putLong(b, o + 9, t1);
        Frames.putLong(b, o + 17, t2);
        long t3 = clock.nowUs();
        Frames.putLong(b, o + 1, t3);
        Frames.putLong(b, o + 25, t3);
        ctx.passDown(Envelope.control(req.peerId(), req.source(), b, o, HEADER_BYTES + 24));
    }

    private void onTimeResponse(LayerContext ctx, Envelope env, long t4) {
        if (env.length() < HEADER_BYTES + 24 || env.peerId() != config.timeSourceId()) {
            ctx.drop(env, "unexpected-time", "a time response that is not from the time source");
            return;
        }
        byte[] d = env.data();
        int o = env.offset();
        long t1 = Frames.getLong(d, o + 9);
        long t2 = Frames.getLong(d, o + 17);
        long t3 = Frames.getLong(d, o + 25);
        if (t1 != pendingT1) {
            ctx.drop(env, "unexpected-time", "a time response to a request this agent did not make last");
            return;
        }
        pendingT1 = Long.MIN_VALUE;
        long roundTrip = (t4 - t1) - (t3 - t2);
        long offset = ((t2 - t1) + (t3 - t4)) / 2;
        exchanges++;
        // Keep the estimate of the fastest exchange: its error is bounded by half its round trip.
        // Let the best round trip age so that a clock that drifts is followed.
        if (bestRoundTripUs != Long.MAX_VALUE) {
            bestRoundTripUs += 1_000;
        }
        if (roundTrip <= bestRoundTripUs) {
            bestRoundTripUs = roundTrip;
            clock.update(clock.offsetUs() + offset, roundTrip);
        }
    }
}
