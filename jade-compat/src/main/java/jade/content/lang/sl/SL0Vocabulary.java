package jade.content.lang.sl;

/** The symbols of FIPA-SL0 (and JADE's basic ontology), as JADE names them. */
public interface SL0Vocabulary {
    /** SL: {@code SEQUENCE}. */
    String SEQUENCE = "sequence";
    /** SL: {@code SET}. */
    String SET = "set";
    /** SL: {@code AID}. */
    String AID = "agent-identifier";
    /** SL: {@code AID_NAME}. */
    String AID_NAME = "name";
    /** SL: {@code AID_ADDRESSES}. */
    String AID_ADDRESSES = "addresses";
    /** SL: {@code AID_RESOLVERS}. */
    String AID_RESOLVERS = "resolvers";
    /** SL: {@code TRUE_PROPOSITION}. */
    String TRUE_PROPOSITION = "true";
    /** SL: {@code FALSE_PROPOSITION}. */
    String FALSE_PROPOSITION = "false";
    /** SL: {@code DONE}. */
    String DONE = "done";
    /** SL: {@code DONE_ACTION}. */
    String DONE_ACTION = "action";
    /** SL: {@code DONE_CONDITION}. */
    String DONE_CONDITION = "condition";
    /** SL: {@code RESULT}. */
    String RESULT = "result";
    /** SL: {@code RESULT_ACTION}. */
    String RESULT_ACTION = "action";
    /** SL: {@code RESULT_VALUE}. */
    String RESULT_VALUE = "value";
    /** SL: {@code RESULT_ITEMS}. */
    String RESULT_ITEMS = "value";
    /** SL: {@code ACTION}. */
    String ACTION = "action";
    /** SL: {@code ACTION_ACTOR}. */
    String ACTION_ACTOR = "actor";
    /** SL: {@code ACTION_ACTION}. */
    String ACTION_ACTION = "action";
    /** SL: {@code EQUALS}. */
    String EQUALS = "=";
    /** SL: {@code EQUALS_LEFT}. */
    String EQUALS_LEFT = "left";
    /** SL: {@code EQUALS_RIGHT}. */
    String EQUALS_RIGHT = "right";
}
