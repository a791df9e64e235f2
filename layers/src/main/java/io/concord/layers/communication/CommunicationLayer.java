package io.concord.layers.communication;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.SendRejectedException;

/**
 * The communication layer, at the bottom: enforces the frame size limit both ways and sends each
 * frame {@code copies} times on UDP against loss. A message too large is refused to the caller
 * with a {@link SendRejectedException} (it never half-leaves); an arriving frame too large is
 * dropped ({@code too-large}), so that no peer can make the agent buffer more than the limit.
 * Copies are filtered above, cheaply: the security layer recognises a frame it accepted by its
 * tag before decrypting it, and the sequence layer drops repeated numbers.
 */
public final class CommunicationLayer extends Layer {
    /** The default limit on UDP: 8 KiB. */
    public static final int DEFAULT_MAX_UDP_BYTES = 8 * 1024;

    /**
     * @param maxFrameBytes the largest frame sent or accepted
     * @param copies        times each frame is sent (1 = no repetition)
     */
    public record Config(int maxFrameBytes, int copies) {
        public Config {
            if (maxFrameBytes < 256 || maxFrameBytes > 65_507) {
                throw new IllegalArgumentException("maxFrameBytes must be 256..65507 (the UDP maximum), got " + maxFrameBytes);
            }
            if (copies < 1 || copies > 5) {
                throw new IllegalArgumentException("copies must be 1..5, got " + copies);
            }
        }
    }

    private final Config config;

    public CommunicationLayer(Config config) {
        this.config = config;
    }

    @Override
    public String name() {
        return "communication";
    }

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        if (env.length() > config.maxFrameBytes()) {
            throw new SendRejectedException("too-large", "the message makes a frame of " + env.length()
                    + " bytes, over the limit of " + config.maxFrameBytes() + " bytes; shorten its content, or raise "
                    + "maxFrameBytes in the communication settings (up to 65507 on UDP)");
        }
        for (int i = 0; i < config.copies(); i++) {
            ctx.passDown(env);
        }
    }

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        if (env.length() > config.maxFrameBytes()) {
            ctx.drop(env, "too-large", "a frame of " + env.length() + " bytes from " + env.source()
                    + ", over the limit of " + config.maxFrameBytes());
            return;
        }
        ctx.passUp(env);
    }
}
