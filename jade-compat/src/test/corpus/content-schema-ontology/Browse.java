import jade.content.AgentAction;

/** The action of listing the books of an author ("browse-books" in the ontology). */
public class Browse implements AgentAction {
    private String author;

    public String getAuthor() {
        return author;
    }

    public void setAuthor(String author) {
        this.author = author;
    }
}
