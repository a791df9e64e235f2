import jade.content.AgentAction;
import jade.content.onto.annotations.Element;
import jade.content.onto.annotations.Slot;

/** The action of listing the books of an author; named "browse-books" in the content. */
@Element(name = "browse-books")
public class Browse implements AgentAction {
    private String author;

    @Slot(name = "by-author", mandatory = true)
    public String getAuthor() {
        return author;
    }

    public void setAuthor(String author) {
        this.author = author;
    }
}
