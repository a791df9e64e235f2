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

    /** Work on core's codec and JADE's ontologies. */
    interface Work<T> {
        T run() throws io.concord.core.content.ContentException, jade.content.onto.OntologyException;
    }

    /** Runs the work, its failures as JADE's codecs report them: a {@link Codec.CodecException} with the reason. */
    static <T> T translated(Work<T> work) throws Codec.CodecException {
        try {
            return work.run();
        } catch (jade.content.onto.OntologyException e) {
            throw new Codec.CodecException(e.getMessage(), e);
        } catch (io.concord.core.content.ContentException e) {
            throw new Codec.CodecException(e.reason(), e);
        }
    }
}
