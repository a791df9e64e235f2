package io.concord.layers.parser;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.codec.AclParseException;
import io.concord.core.codec.BinaryAclCodec;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.layer.StackEvent;
import io.concord.layers.frame.Frames;
import io.concord.layers.sequence.SequenceLayer;
import io.concord.layers.temporal.PlatformClock;

import java.util.HashMap;
import java.util.Map;

/**
 * The parser layer: ACL to bytes and back (Concord's binary codec), and the checks that need the
 * message itself. Receiving, it drops and counts: what does not decode ({@code malformed}); a
 * sender whose name does not belong to the authenticated frame source, or that speaks from an
 * address other than the one the agent lists know ({@code identification}); a sender that is not a
 * member ({@code not-member}; if it is joining, the sender is asked to send again); and a message
 * whose {@code :reply-by} has passed on the platform clock ({@code expired}).
 */
public final class ParserLayer extends Layer {
    private final Membership membership;
    private final PlatformClock clock;
    private final boolean identification;
    private final int maxFrameBytes;
    private final int overheadBytes;
    private final Map<String, Long> ids = new HashMap<>();
    // A message to several receivers is encoded once; each envelope gets its own copy of the bytes.
    private AclMessage lastEncoded;
    private byte[] lastBytes;
    private int lastLength;

    /** A parser with no frame limit of its own (the communication layer still enforces one). */
    public ParserLayer(Membership membership, PlatformClock clock, boolean identification) {
        this(membership, clock, identification, Integer.MAX_VALUE, 0);
    }

    /**
     * @param membership     who belongs to the platform
     * @param clock          the platform clock, for {@code :reply-by}; {@code null} to skip that check
     * @param identification true to require the sender to match the authenticated frame source
     * @param maxFrameBytes  the frame limit of the stack, checked here before any layer queues the
     *                       message (a handshake may hold it), so that the caller hears of it
     * @param overheadBytes  the bytes the layers below add to a message
     */
    public ParserLayer(Membership membership, PlatformClock clock, boolean identification, int maxFrameBytes,
                       int overheadBytes) {
        this.membership = membership;
        this.clock = clock;
        this.identification = identification;
        this.maxFrameBytes = maxFrameBytes;
        this.overheadBytes = overheadBytes;
    }

    @Override
    public String name() {
        return "parser";
    }

    private long idOf(AID aid) {
        Long id = ids.get(aid.name());
        if (id == null) {
            if (Frames.ANY_LOCAL_NAME.equals(aid.localName())) {
                return Frames.ANY;
            }
            if (ids.size() > 10_000) {
                ids.clear();
            }
            id = Frames.id(aid.name());
            ids.put(aid.name(), id);
        }
        return id;
    }

    @Override
    public void init(LayerContext ctx) {
        if (clock != null) {
            clock.bind(ctx.host().clock());
        }
    }

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        byte[] bytes;
        int aclBytes;
        // Valid only within one send: it walks the receivers in order, so the first receiver always
        // encodes afresh (the caller may have changed and re-sent the same message object).
        if (env.message() == lastEncoded && env.receiver() != env.message().getReceivers().get(0)) {
            aclBytes = lastLength;
            bytes = new byte[Frames.HEADROOM + aclBytes + 40];
            System.arraycopy(lastBytes, Frames.HEADROOM, bytes, Frames.HEADROOM, aclBytes);
        } else {
            // Room for the headers, the content (it is copied once, not grown into) and the tags below.
            String text = env.message().hasByteSequenceContent() ? null : env.message().getContent();
            BinaryAclCodec.Writer w = new BinaryAclCodec.Writer(Frames.HEADROOM + 320 + (text == null ? 0 : text.length()));
            w.skip(Frames.HEADROOM);
            BinaryAclCodec.INSTANCE.encode(env.message(), w);
            bytes = w.array();
            aclBytes = w.size() - Frames.HEADROOM;
            boolean several = env.message().getReceivers().size() > 1;
            lastEncoded = several ? env.message() : null;
            lastBytes = several ? bytes.clone() : null;
            lastLength = aclBytes;
        }
        if ((long) aclBytes + overheadBytes > maxFrameBytes) {
            throw new SendRejectedException("too-large", "the message to "
                    + env.receiver().name() + " encodes to " + aclBytes + " bytes; with the stack's " + overheadBytes
                    + " bytes of headers its frame would be " + (aclBytes + overheadBytes) + " bytes, over the limit of "
                    + maxFrameBytes + "; shorten its content, or raise maxFrameBytes (up to 65507 on UDP)");
        }
        env.setData(bytes, Frames.HEADROOM, aclBytes);
        AID via = env.header(Frames.ENVELOPE_VIA);
        env.setPeerId(idOf(via != null ? via : env.receiver()));
        ctx.passDown(env);
    }

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        AclMessage m;
        try {
            m = BinaryAclCodec.INSTANCE.decode(env.data(), env.offset(), env.length());
        } catch (AclParseException e) {
            ctx.drop(env, "malformed", e.getMessage());
            return;
        }
        AID sender = m.getSender();
        if (sender == null) {
            ctx.drop(env, "identification", "the message names no sender");
            return;
        }
        if (identification && idOf(sender) != env.peerId()) {
            ctx.drop(env, "identification", "the message claims to be from " + sender.name()
                    + " but the frame is authenticated as another agent's");
            return;
        }
        if (env.header(Frames.ENVELOPE_ANY) != null && !Membership.PLATFORM_ONTOLOGY.equals(m.getOntology())) {
            ctx.drop(env, "unprotected", "a message addressed to any agent at this port that is not platform discovery");
            return;
        }
        switch (membership.check(m, sender, env.source())) {
            case MEMBER, EXEMPT -> { }
            case WRONG_SOURCE -> {
                ctx.drop(env, "identification", sender.name() + " spoke from " + env.source()
                        + ", not from the address the agent lists know for it");
                return;
            }
            case PENDING -> {
                ctx.drop(env, "not-member", sender.name() + " is joining but not yet a member; asked to send again");
                ctx.fireEvent(new StackEvent(SequenceLayer.RESEND_REQUEST, env, false));
                return;
            }
            case UNKNOWN -> {
                ctx.drop(env, "not-member", sender.name() + " is not a member of this platform");
                return;
            }
        }
        if (clock != null && m.hasReplyBy() && m.getReplyByEpochMs() < clock.nowMs()) {
            ctx.drop(env, "expired", "its :reply-by passed " + (clock.nowMs() - m.getReplyByEpochMs())
                    + " ms ago on the platform clock");
            return;
        }
        env.setMessage(m);
        ctx.passUp(env);
    }
}
