package jade.content.lang.sl;

import io.concord.core.content.AbsObject;
import io.concord.core.content.SlCodec;
import io.concord.jadecompat.internal.AbsElements;
import io.concord.jadecompat.internal.ContentCodec;
import jade.content.abs.AbsContentElement;
import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.lang.StringCodec;
import jade.lang.acl.ACLMessage;

import java.util.List;

/**
 * FIPA-SL, as JADE's {@code SLCodec}: Concord's {@link SlCodec}, which writes the text JADE 4.3
 * writes for the same content and reads what it writes. {@code SLCodec(0)}, {@code (1)},
 * {@code (2)} are the SL0, SL1, SL2 profiles (languages {@code fipa-sl0}, ...); any other profile
 * and the default are full SL ({@code fipa-sl}). {@code preserveJavaTypes} is recorded, not
 * applied: numbers are written as plain SL numbers.
 */
public class SLCodec extends StringCodec implements ContentCodec {
    private static final long serialVersionUID = 1L;
    /** JADE's name of the preserve-Java-types option. */
    public static final String PRESERVE_JAVA_TYPES = "SL-preserve-java-types";

    private final transient SlCodec codec;
    private final boolean preserveJavaTypes;

    /** Full SL. */
    public SLCodec() {
        this(3, false);
    }

    /** Full SL; the flag is recorded only. */
    public SLCodec(boolean preserveJavaTypes) {
        this(3, preserveJavaTypes);
    }

    /** The profile 0, 1, 2 (SL0, SL1, SL2) or full SL for any other. */
    public SLCodec(int slType) {
        this(slType, false);
    }

    /** The profile and the (recorded) flag. */
    public SLCodec(int slType, boolean preserveJavaTypes) {
        this(profile(slType), preserveJavaTypes);
    }

    private SLCodec(SlCodec.Profile profile, boolean preserveJavaTypes) {
        super(profile.languageName());
        this.codec = new SlCodec(profile, SlCodec.DEFAULT_MAX_DEPTH, SlCodec.DEFAULT_MAX_CHARS);
        this.preserveJavaTypes = preserveJavaTypes;
    }

    private static SlCodec.Profile profile(int slType) {
        return switch (slType) {
            case 0 -> SlCodec.Profile.SL0;
            case 1 -> SlCodec.Profile.SL1;
            case 2 -> SlCodec.Profile.SL2;
            default -> SlCodec.Profile.SL;
        };
    }

    /** Whether the codec was asked to preserve Java types (recorded, not applied). */
    public boolean getPreserveJavaTypes() {
        return preserveJavaTypes;
    }

    @Override
    public String encode(AbsContentElement content) throws CodecException {
        return encode(BasicOntology.getInstance(), content);
    }

    @Override
    public String encode(Ontology ontology, AbsContentElement content) throws CodecException {
        return ContentCodec.translated(() -> codec.write(AbsElements.toCore(ontology, content)));
    }

    @Override
    public AbsContentElement decode(String content) throws CodecException {
        return decode(BasicOntology.getInstance(), content);
    }

    @Override
    public AbsContentElement decode(Ontology ontology, String content) throws CodecException {
        return ContentCodec.translated(() -> AbsElements.fromCore(ontology, codec.read(content)));
    }

    @Override
    public void writeContent(ACLMessage message, List<AbsObject> elements) throws CodecException {
        message.setContent(ContentCodec.translated(() -> codec.write(elements)));
    }

    @Override
    public List<AbsObject> readContent(ACLMessage message) throws CodecException {
        String text = message.getContent();
        if (text == null) {
            throw new CodecException("the message has no content");
        }
        return ContentCodec.translated(() -> codec.read(text));
    }
}
