package jade.content.lang;

import jade.content.abs.AbsContentElement;
import jade.content.onto.Ontology;

/** A codec whose content is bytes, such as {@link jade.content.lang.leap.LEAPCodec}. */
public abstract class ByteArrayCodec extends Codec {
    private static final long serialVersionUID = 1L;

    /** A byte codec for that language name. */
    public ByteArrayCodec(String name) {
        super(name);
    }

    /** Writes an abstract content element (the basic ontology's elements only). */
    public abstract byte[] encode(AbsContentElement content) throws CodecException;

    /** Writes an abstract content element of that ontology. */
    public abstract byte[] encode(Ontology ontology, AbsContentElement content) throws CodecException;

    /** Reads a content as an abstract element (the basic ontology's elements only). */
    public abstract AbsContentElement decode(byte[] content) throws CodecException;

    /** Reads a content of that ontology as an abstract element. */
    public abstract AbsContentElement decode(Ontology ontology, byte[] content) throws CodecException;
}
