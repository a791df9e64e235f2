package jade.content.abs;

import jade.content.Term;

/** An abstract term: a concept, a primitive, an aggregate or a variable. */
public interface AbsTerm extends AbsObject, Term {
}
