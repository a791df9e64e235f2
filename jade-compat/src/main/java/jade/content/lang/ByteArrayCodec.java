package jade.content.lang;

/** A codec whose content is bytes, such as {@link jade.content.lang.leap.LEAPCodec}. */
public abstract class ByteArrayCodec extends Codec {
    private static final long serialVersionUID = 1L;

    /** A byte codec for that language name. */
    public ByteArrayCodec(String name) {
        super(name);
    }
}
