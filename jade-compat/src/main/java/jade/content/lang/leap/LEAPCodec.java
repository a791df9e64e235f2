package jade.content.lang.leap;

import io.concord.core.content.AbsObject;
import io.concord.core.content.BinaryContentCodec;
import io.concord.jadecompat.internal.AbsElements;
import io.concord.jadecompat.internal.ContentCodec;
import jade.content.abs.AbsContentElement;
import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
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
        return ContentCodec.translated(() -> codec.write(AbsElements.toCore(ontology, content)));
    }

    @Override
    public AbsContentElement decode(byte[] content) throws CodecException {
        return decode(BasicOntology.getInstance(), content);
    }

    @Override
    public AbsContentElement decode(Ontology ontology, byte[] content) throws CodecException {
        return ContentCodec.translated(() -> AbsElements.fromCore(ontology, codec.read(content)));
    }

    @Override
    public void writeContent(ACLMessage message, List<AbsObject> elements) throws CodecException {
        message.setByteSequenceContent(ContentCodec.translated(() -> codec.write(elements)));
    }

    @Override
    public List<AbsObject> readContent(ACLMessage message) throws CodecException {
        byte[] bytes = message.getByteSequenceContent();
        if (bytes == null) {
            throw new CodecException("the message has no content");
        }
        return ContentCodec.translated(() -> codec.read(bytes));
    }
}
