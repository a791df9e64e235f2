package io.concord.jadecompat.internal;

import io.concord.core.content.AbsObject;
import jade.content.lang.Codec;
import jade.lang.acl.ACLMessage;

import java.util.List;

/** How {@code jade.content.ContentManager} reaches the core codec behind a JADE-named codec. */
public interface ContentCodec {
    /** Writes these elements as the message's content. */
    void writeContent(ACLMessage message, List<AbsObject> elements) throws Codec.CodecException;

    /** Reads the message's content as abstract elements. */
    List<AbsObject> readContent(ACLMessage message) throws Codec.CodecException;
}
