package jade.content;

/** JADE's marker of an agent action: a concept that an agent can be asked to carry out. */
public interface AgentAction extends ContentElement, Concept {
}
