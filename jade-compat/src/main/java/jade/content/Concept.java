package jade.content;

/** JADE's marker of a concept: an entity of an ontology (a bean with a schema). */
public interface Concept extends Term {
}
