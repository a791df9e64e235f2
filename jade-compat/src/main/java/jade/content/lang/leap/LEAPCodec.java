package jade.content.lang.leap;

import io.concord.core.content.AbsObject;
import io.concord.core.content.BinaryContentCodec;
import io.concord.core.content.ContentException;
import io.concord.jadecompat.internal.AbsElements;
import io.concord.jadecompat.internal.ContentCodec;
import jade.content.abs.AbsContentElement;
import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.lang.ByteArrayCodec;
import jade.lang.acl.ACLMessage;

import java.util.List;

/**
 * The binary content language registered as {@code LEAP}, as JADE's {@code LEAPCodec} is. Its bytes
 * are Concord's binary encoding ({@link BinaryContentCodec}, see docs/content.md), not JADE's LEAP
 * bytes: Concord agents read each other's, a JADE agent cannot read them (nor they JADE's).
 */
public class LEAPCodec extends ByteArrayCodec implements ContentCodec {
    private static final long serialVersionUID = 1L;
    /** The language's name. */
    public static final String NAME = "LEAP";

    private final transient BinaryContentCodec codec = new BinaryContentCodec();

    /** The codec. */
    public LEAPCodec() {
        super(NAME);
    }

    @Override
    public byte[] encode(AbsContentElement content) throws CodecException {
        return encode(BasicOntology.getInstance(), content);
    }

    @Override
    public byte[] encode(Ontology ontology, AbsContentElement content) throws CodecException {
        try {
            return codec.write(AbsElements.toCore(ontology, content));
        } catch (OntologyException e) {
            throw new CodecException(e.getMessage(), e);
        } catch (ContentException e) {
            throw new CodecException(e.reason(), e);
        }
    }

    @Override
    public AbsContentElement decode(byte[] content) throws CodecException {
        return decode(BasicOntology.getInstance(), content);
    }

    @Override
    public AbsContentElement decode(Ontology ontology, byte[] content) throws CodecException {
        try {
            return AbsElements.fromCore(ontology, codec.read(content));
        } catch (OntologyException e) {
            throw new CodecException(e.getMessage(), e);
        } catch (ContentException e) {
            throw new CodecException(e.reason(), e);
        }
    }

    @Override
    public void writeContent(ACLMessage message, List<AbsObject> elements) throws CodecException {
        try {
            message.setByteSequenceContent(codec.write(elements));
        } catch (ContentException e) {
            throw new CodecException(e.reason(), e);
        }
    }

    @Override
    public List<AbsObject> readContent(ACLMessage message) throws CodecException {
        byte[] bytes = message.getByteSequenceContent();
        if (bytes == null) {
            throw new CodecException("the message has no content");
        }
        try {
            return codec.read(bytes);
        } catch (ContentException e) {
            throw new CodecException(e.reason(), e);
        }
    }
}
