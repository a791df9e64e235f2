package jade.content.lang;

import jade.content.abs.AbsContentElement;
import jade.content.onto.Ontology;

/** A codec whose content is text, such as {@link jade.content.lang.sl.SLCodec}. */
public abstract class StringCodec extends Codec {
    private static final long serialVersionUID = 1L;

    /** A text codec for that language name. */
    public StringCodec(String name) {
        super(name);
    }

    /** Writes an abstract content element (the basic ontology's elements only). */
    public abstract String encode(AbsContentElement content) throws CodecException;

    /** Writes an abstract content element of that ontology. */
    public abstract String encode(Ontology ontology, AbsContentElement content) throws CodecException;

    /** Reads a content as an abstract element (the basic ontology's elements only). */
    public abstract AbsContentElement decode(String content) throws CodecException;

    /** Reads a content of that ontology as an abstract element. */
    public abstract AbsContentElement decode(Ontology ontology, String content) throws CodecException;
}
