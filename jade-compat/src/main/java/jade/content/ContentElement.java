package jade.content;

/** JADE's marker of what can be a message's content: a predicate or an agent action. */
public interface ContentElement extends jade.util.leap.Serializable {
}
