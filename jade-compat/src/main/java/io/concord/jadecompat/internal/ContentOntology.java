package io.concord.jadecompat.internal;

import io.concord.core.content.AbsObject;
import jade.content.onto.OntologyException;

/** How {@code jade.content.ContentManager} maps Java objects through a JADE-named ontology. */
public interface ContentOntology {
    /** The abstract form of a Java object, checked against the schemas. */
    AbsObject toAbs(Object value) throws OntologyException;

    /** The Java object of an abstract form; with {@code validate}, mandatory slots and cardinalities are checked. */
    Object fromAbs(AbsObject abs, boolean validate) throws OntologyException;
}
