package jade.content.lang;

/** A codec whose content is text, such as {@link jade.content.lang.sl.SLCodec}. */
public abstract class StringCodec extends Codec {
    private static final long serialVersionUID = 1L;

    /** A text codec for that language name. */
    public StringCodec(String name) {
        super(name);
    }
}
