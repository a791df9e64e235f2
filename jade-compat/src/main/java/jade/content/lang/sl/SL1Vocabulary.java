package jade.content.lang.sl;

/** The symbols FIPA-SL1 adds: {@code and}, {@code or}, {@code not}. */
public interface SL1Vocabulary extends SL0Vocabulary {
    /** SL: {@code AND}. */
    String AND = "and";
    /** SL: {@code AND_LEFT}. */
    String AND_LEFT = "left";
    /** SL: {@code AND_RIGHT}. */
    String AND_RIGHT = "right";
    /** SL: {@code OR}. */
    String OR = "or";
    /** SL: {@code OR_LEFT}. */
    String OR_LEFT = "left";
    /** SL: {@code OR_RIGHT}. */
    String OR_RIGHT = "right";
    /** SL: {@code NOT}. */
    String NOT = "not";
    /** SL: {@code NOT_WHAT}. */
    String NOT_WHAT = "what";
}
