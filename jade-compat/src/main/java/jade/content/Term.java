package jade.content;

/** JADE's marker of a term: something a slot can hold. */
public interface Term extends jade.util.leap.Serializable {
}
