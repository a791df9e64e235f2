package jade.content;

/** JADE's marker of a predicate: a proposition, true or false. */
public interface Predicate extends ContentElement {
}
