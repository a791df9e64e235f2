package jade.content;

import io.concord.core.content.AbsObject;
import io.concord.jadecompat.internal.ContentCodec;
import io.concord.jadecompat.internal.AbsElements;
import jade.content.abs.AbsContentElement;
import jade.content.lang.ByteArrayCodec;
import jade.content.lang.StringCodec;
import jade.content.lang.Codec;
import jade.content.lang.Codec.CodecException;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.onto.UngroundedException;
import jade.lang.acl.ACLMessage;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Fills a message's content from Java objects and extracts it back, as JADE's: the message's
 * {@code :language} picks a registered codec and its {@code :ontology} a registered ontology (both
 * must be set on the message, as in JADE). An unknown language is a {@link CodecException}, an
 * unknown ontology an {@link OntologyException}, malformed text a {@link CodecException}, content
 * that breaks its schema an {@link OntologyException}, a variable where a value is needed an
 * {@link UngroundedException}. Each agent has one ({@code Agent.getContentManager()}).
 */
public class ContentManager implements jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;
    private final Map<String, Codec> languages = new LinkedHashMap<>();
    private final Map<String, Ontology> ontologies = new LinkedHashMap<>();
    private boolean validationMode = true;

    /** An empty content manager. */
    public ContentManager() {
    }

    /** Registers a codec under its name. */
    public void registerLanguage(Codec codec) {
        if (codec == null) {
            throw new IllegalArgumentException("Null codec registered");
        }
        registerLanguage(codec, codec.getName());
    }

    /** Registers a codec under that name. */
    public void registerLanguage(Codec codec, String name) {
        if (codec == null) {
            throw new IllegalArgumentException("Null codec registered");
        }
        languages.put(name, codec);
    }

    /** Registers an ontology under its name. */
    public void registerOntology(Ontology ontology) {
        if (ontology == null) {
            throw new IllegalArgumentException("Null ontology registered");
        }
        registerOntology(ontology, ontology.getName());
    }

    /** Registers an ontology under that name. */
    public void registerOntology(Ontology ontology, String name) {
        if (ontology == null) {
            throw new IllegalArgumentException("Null ontology registered");
        }
        ontologies.put(name, ontology);
    }

    /** The codec registered under that name, or null. */
    public Codec lookupLanguage(String name) {
        return name == null ? null : languages.get(name);
    }

    /** The ontology registered under that name, or null. */
    public Ontology lookupOntology(String name) {
        return name == null ? null : ontologies.get(name);
    }

    /** The ontology the message names, or null. */
    public Ontology getOntology(ACLMessage message) {
        return lookupOntology(message.getOntology());
    }

    /** The names of the registered languages. */
    public String[] getLanguageNames() {
        return languages.keySet().toArray(new String[0]);
    }

    /** The names of the registered ontologies. */
    public String[] getOntologyNames() {
        return ontologies.keySet().toArray(new String[0]);
    }

    /** Whether extracted content is checked against the schemas (mandatory slots, cardinality, types); on by default. */
    public void setValidationMode(boolean mode) {
        this.validationMode = mode;
    }

    /** Whether extracted content is checked against the schemas. */
    public boolean getValidationMode() {
        return validationMode;
    }

    /**
     * Writes the element (a {@link ContentElementList} for several) as the message's content in its
     * language and ontology.
     */
    public void fillContent(ACLMessage message, ContentElement content) throws CodecException, OntologyException {
        Codec codec = codec(message);
        Ontology ontology = ontology(message);
        if (content == null) {
            throw new OntologyException("null content");
        }
        List<AbsObject> elements = new ArrayList<>();
        if (content instanceof ContentElementList list) {
            for (int i = 0; i < list.size(); i++) {
                elements.add(ontology.toAbs(list.get(i)));
            }
        } else {
            elements.add(ontology.toAbs(content));
        }
        write(codec, message, ontology, elements);
    }

    /** Writes an abstract content element (a list for several) as the message's content. */
    public void fillContent(ACLMessage message, AbsContentElement content) throws CodecException, OntologyException {
        Codec codec = codec(message);
        Ontology ontology = ontology(message);
        write(codec, message, ontology, AbsElements.toCore(ontology, content));
    }

    /** Reads the message's content as abstract descriptors (a list for several elements), checked only by the codec. */
    public AbsContentElement extractAbsContent(ACLMessage message) throws CodecException, OntologyException {
        Codec codec = codec(message);
        Ontology ontology = ontology(message);
        return AbsElements.fromCore(ontology, read(codec, message, ontology));
    }

    private static void write(Codec codec, ACLMessage message, Ontology ontology, List<AbsObject> elements)
            throws CodecException, OntologyException {
        if (codec instanceof ContentCodec c) {
            c.writeContent(message, elements);
        } else if (codec instanceof StringCodec c) {
            message.setContent(c.encode(ontology, AbsElements.fromCore(ontology, elements)));
        } else if (codec instanceof ByteArrayCodec c) {
            message.setByteSequenceContent(c.encode(ontology, AbsElements.fromCore(ontology, elements)));
        } else {
            throw new CodecException("codec " + codec.getName() + " is neither a StringCodec nor a ByteArrayCodec");
        }
    }

    private static List<AbsObject> read(Codec codec, ACLMessage message, Ontology ontology) throws CodecException, OntologyException {
        if (codec instanceof ContentCodec c) {
            return c.readContent(message);
        }
        if (codec instanceof StringCodec c) {
            if (message.getContent() == null) {
                throw new CodecException("the message has no content");
            }
            return AbsElements.toCore(ontology, c.decode(ontology, message.getContent()));
        }
        if (codec instanceof ByteArrayCodec c) {
            if (message.getByteSequenceContent() == null) {
                throw new CodecException("the message has no content");
            }
            return AbsElements.toCore(ontology, c.decode(ontology, message.getByteSequenceContent()));
        }
        throw new CodecException("codec " + codec.getName() + " is neither a StringCodec nor a ByteArrayCodec");
    }

    /**
     * Reads the message's content as Java objects: a predicate or an agent action (such as
     * {@code Action}), or a {@link ContentElementList} when the content has several elements.
     */
    public ContentElement extractContent(ACLMessage message) throws CodecException, UngroundedException, OntologyException {
        Codec codec = codec(message);
        Ontology ontology = ontology(message);
        List<AbsObject> elements = read(codec, message, ontology);
        if (elements.isEmpty()) {
            throw new CodecException("the content has no element");
        }
        List<ContentElement> out = new ArrayList<>();
        for (AbsObject abs : elements) {
            Object o = ontology.fromAbs(abs, validationMode);
            if (!(o instanceof ContentElement ce)) {
                throw new OntologyException("content element " + o.getClass().getSimpleName()
                        + " is neither a predicate nor an agent action");
            }
            out.add(ce);
        }
        if (out.size() == 1) {
            return out.get(0);
        }
        ContentElementList list = new ContentElementList();
        for (ContentElement ce : out) {
            list.add(ce);
        }
        return list;
    }

    private Codec codec(ACLMessage message) throws CodecException {
        Codec codec = lookupLanguage(message.getLanguage());
        if (codec == null) {
            throw new CodecException("Unknown language " + message.getLanguage());
        }
        return codec;
    }

    private Ontology ontology(ACLMessage message) throws OntologyException {
        Ontology ontology = lookupOntology(message.getOntology());
        if (ontology == null) {
            throw new OntologyException("Unknown ontology " + message.getOntology());
        }
        return ontology;
    }

    @Override
    public String toString() {
        return "(ContentManager: languages " + languages.keySet() + ", ontologies " + ontologies.keySet() + ")";
    }
}
