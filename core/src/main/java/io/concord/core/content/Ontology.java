package io.concord.core.content;

import java.util.Collection;

/**
 * A vocabulary: the schemas of the content agents exchange, and the mapping between Java objects
 * and abstract content ({@link AbsObject}) that checks each value against its schema.
 */
public interface Ontology {

    /** The value of the message's {@code :ontology} slot. */
    String name();

    /** The schema of that symbol, or null when it has none (here or in the basic ontology). */
    Schema schema(String symbol);

    /** All schemas of this ontology, not counting the basic ontology's. */
    Collection<Schema> schemas();

    /**
     * The abstract form of a Java object.
     *
     * @throws ContentException if the object, or a part of it, has no schema or breaks its facets
     */
    AbsObject toAbs(Object value) throws ContentException;

    /**
     * The Java object of an abstract form, checked against the schemas.
     *
     * @throws ContentException naming the symbol and slot that has no schema or breaks its facets
     */
    Object fromAbs(AbsObject abs) throws ContentException;
}
