package io.concord.layers.communication;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.net.Transport;

/**
 * The communication layer, at the bottom: enforces the frame size limit both ways (8 KiB on UDP
 * and 16 KiB on TCP by default) and sends each frame {@code copies} times on UDP against loss (once
 * to an agent of the same runtime, whose frames are handed over in memory). A message too large is refused to the caller
 * with a {@link SendRejectedException} (it never half-leaves); an arriving frame too large is
 * dropped ({@code too-large}), so that no peer can make the agent buffer more than the limit.
 * Copies are filtered above, cheaply: the security layer recognises a frame it accepted by its
 * tag before decrypting it, and the sequence layer drops repeated numbers.
 */
public final class CommunicationLayer extends Layer {
    /** The default limit on UDP: 8 KiB. */
    public static final int DEFAULT_MAX_UDP_BYTES = 8 * 1024;
    /** The default limit on TCP: 16 KiB. */
    public static final int DEFAULT_MAX_TCP_BYTES = 16 * 1024;

    /**
     * @param transport     the transport the agent must be started on
     * @param maxFrameBytes the largest frame sent or accepted
     * @param copies        times each frame is sent (1 = no repetition; TCP needs none)
     */
    public record Config(Transport transport, int maxFrameBytes, int copies) {
        public Config {
            int max = transport == Transport.UDP ? 65_507 : 1 << 20;
            if (maxFrameBytes < 256 || maxFrameBytes > max) {
                throw new IllegalArgumentException("maxFrameBytes must be 256.." + max + " on " + transport + ", got "
                        + maxFrameBytes);
            }
            if (copies < 1 || copies > 5) {
                throw new IllegalArgumentException("copies must be 1..5, got " + copies);
            }
            if (transport == Transport.TCP && copies != 1) {
                throw new IllegalArgumentException("repetition is for UDP: TCP already retransmits; use copies(1)");
            }
        }

        /** UDP with the given limit and copies. */
        public Config(int maxFrameBytes, int copies) {
            this(Transport.UDP, maxFrameBytes, copies);
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
    public void init(LayerContext ctx) {
        if (ctx.host().transport() != config.transport()) {
            throw new IllegalStateException("this stack was built for " + config.transport() + " but the agent runs on "
                    + ctx.host().transport() + "; build the stack with transport(" + ctx.host().transport()
                    + ") or start the agent on " + config.transport());
        }
    }

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        if (env.length() > config.maxFrameBytes()) {
            throw new SendRejectedException("too-large", "the message makes a frame of " + env.length()
                    + " bytes, over the limit of " + config.maxFrameBytes() + " bytes; shorten its content, or raise "
                    + "maxFrameBytes in the communication settings (up to 65507 on UDP)");
        }
        // Repetition is against loss on the network; a frame handed over in memory cannot be lost.
        int copies = config.copies() == 1 || ctx.host().inMemoryTo(env.destination()) ? 1 : config.copies();
        for (int i = 0; i < copies; i++) {
            env.lane(i); // each copy in a datagram of its own: one lost datagram never takes two
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
