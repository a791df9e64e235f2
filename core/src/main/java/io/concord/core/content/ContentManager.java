package io.concord.core.content;

import io.concord.core.acl.AclMessage;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Fills a message's content from Java objects and extracts it back, as JADE's
 * {@code ContentManager} does: the message's {@code :language} picks the codec and its
 * {@code :ontology} the ontology, both registered beforehand. Every failure is a
 * {@link ContentException} whose {@link ContentException#reason() reason} can be sent back in a
 * NOT-UNDERSTOOD. Not thread-safe while registering; safe to share once set up.
 */
public final class ContentManager {
    private final Map<String, Object> languages = new LinkedHashMap<>();
    private final Map<String, Ontology> ontologies = new LinkedHashMap<>();

    /** Registers a codec under its language name (such as {@code fipa-sl}). */
    public ContentManager register(SlCodec codec) {
        languages.put(codec.languageName(), codec);
        return this;
    }

    /** Registers the binary codec under {@value BinaryContentCodec#LANGUAGE}; its content travels as bytes. */
    public ContentManager register(BinaryContentCodec codec) {
        languages.put(codec.languageName(), codec);
        return this;
    }

    /** Registers an ontology under its name. */
    public ContentManager register(Ontology ontology) {
        ontologies.put(ontology.name(), ontology);
        return this;
    }

    /**
     * Writes one content element into the message and sets its language and ontology (the first
     * registered of each unless the message already names one).
     *
     * @param content a {@link Predicate}, an {@link Action}, or an abstract proposition or
     *                referential expression ({@link AbsCompound})
     * @throws ContentException if the content cannot be a message's content or breaks its schema
     */
    public void fill(AclMessage message, Object content) throws ContentException {
        Objects.requireNonNull(content, "content");
        Object codec = pick(languages, message.getLanguage(), "language");
        Ontology ontology = pick(ontologies, message.getOntology(), "ontology");
        if (!(content instanceof Predicate || content instanceof Action || content instanceof AbsCompound)) {
            throw new ContentException("a " + content.getClass().getSimpleName()
                    + " cannot be content on its own: wrap an action in Action, or send a predicate");
        }
        AbsObject abs = ontology.toAbs(content);
        if (codec instanceof SlCodec sl) {
            message.setContent(sl.write(abs));
            message.setLanguage(sl.languageName());
        } else {
            BinaryContentCodec binary = (BinaryContentCodec) codec;
            message.setByteSequenceContent(binary.write(List.of(abs)));
            message.setLanguage(binary.languageName());
        }
        message.setOntology(ontology.name());
    }

    /**
     * Reads the message's content: one element, checked against the ontology's schemas.
     *
     * @return a {@link Predicate} or an {@link Action}
     * @throws ContentException if the language or ontology is unknown, the text malformed, or the
     *                          content breaks its schema
     */
    public Object extract(AclMessage message) throws ContentException {
        List<Object> all = extractAll(message);
        if (all.size() != 1) {
            throw new ContentException("expected one content element, got " + all.size());
        }
        return all.get(0);
    }

    /** Reads every element of the message's content; see {@link #extract(AclMessage)}. */
    public List<Object> extractAll(AclMessage message) throws ContentException {
        Ontology ontology = named(ontologies, message.getOntology(), "ontology");
        List<Object> out = new ArrayList<>();
        for (AbsObject abs : extractAbs(message)) {
            if (abs instanceof AbsPrimitive p && p.value() instanceof Boolean b) {
                out.add(b ? new TrueProposition() : new FalseProposition());
                continue;
            }
            Schema schema = abs instanceof AbsCompound c ? ontology.schema(c.name()) : null;
            if (schema == null || !(schema.kind() == Schema.Kind.PREDICATE || schema.javaClass() == Action.class)) {
                throw new ContentException("content element " + describe(abs) + " is neither a proposition nor an action");
            }
            out.add(ontology.fromAbs(abs));
        }
        return out;
    }

    /**
     * Reads the message's content without mapping it to Java objects: for propositions with
     * logical operators or referential expressions ({@code and}, {@code iota}, ...), which have
     * no Java class.
     */
    public List<AbsObject> extractAbs(AclMessage message) throws ContentException {
        Object codec = named(languages, message.getLanguage(), "language");
        if (codec instanceof BinaryContentCodec binary) {
            byte[] bytes = message.getByteSequenceContent();
            if (bytes == null) {
                throw new ContentException("the message has no content");
            }
            return binary.read(bytes);
        }
        if (message.getContent() == null) {
            throw new ContentException("the message has no content");
        }
        return ((SlCodec) codec).read(message.getContent());
    }

    private static String describe(AbsObject abs) {
        return abs instanceof AbsCompound c ? c.name() : abs.getClass().getSimpleName();
    }

    private static <T> T pick(Map<String, T> registered, String name, String what) throws ContentException {
        if (name != null) {
            return named(registered, name, what);
        }
        if (registered.isEmpty()) {
            throw new ContentException("no " + what + " registered");
        }
        return registered.values().iterator().next();
    }

    private static <T> T named(Map<String, T> registered, String name, String what) throws ContentException {
        T t = name == null ? null : registered.get(name);
        if (t == null) {
            throw new ContentException("unknown " + what + " " + name);
        }
        return t;
    }
}
