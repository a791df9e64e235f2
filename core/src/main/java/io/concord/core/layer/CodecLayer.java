package io.concord.core.layer;

import io.concord.core.acl.AclMessage;
import io.concord.core.codec.AclCodec;
import io.concord.core.codec.AclParseException;
import io.concord.core.codec.BinaryAclCodec;

/**
 * Turns messages into bytes going down and bytes into messages going up. A message that does not
 * decode is dropped with reason {@code "malformed"} and the parse error in the trace; it never
 * reaches the agent.
 */
public final class CodecLayer extends Layer {
    private final AclCodec codec;

    /** A codec layer with Concord's binary codec. */
    public CodecLayer() {
        this(BinaryAclCodec.INSTANCE);
    }

    public CodecLayer(AclCodec codec) {
        this.codec = codec;
    }

    @Override
    public String name() {
        return "codec";
    }

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        byte[] bytes = codec.encode(env.message());
        env.setData(bytes, 0, bytes.length);
        ctx.passDown(env);
    }

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        AclMessage m;
        try {
            m = codec.decode(env.data(), env.offset(), env.length());
        } catch (AclParseException e) {
            ctx.drop(env, "malformed", e.getMessage());
            return;
        }
        env.setMessage(m);
        ctx.passUp(env);
    }
}
